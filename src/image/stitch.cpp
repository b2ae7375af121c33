#include "image/stitch.hpp"

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <utility>

#include "image/image_checks.hpp"
#include "image/image_limits.hpp"

namespace clrt {
namespace {

// A tile's pixels in full-frame coordinates, half-open: [x0, x1) x [y0, y1).
struct Rect {
  int x0 = 0, x1 = 0, y0 = 0, y1 = 0;
  std::int64_t pixels() const { return std::int64_t{x1 - x0} * (y1 - y0); }
};

std::string rect_text(const Rect& r) {
  return "x [" + std::to_string(r.x0) + ", " + std::to_string(r.x1) + ") y [" +
         std::to_string(r.y0) + ", " + std::to_string(r.y1) + ")";
}

Placement placement_of(const TileExtent& tile) {
  return tile.placement.value_or(Placement{0, 0, tile.width, tile.height});
}

TileExtent extent_of(const TileImage& tile) {
  return std::visit(
      [&](const auto& i) { return TileExtent{tile.name, i.width, i.height, i.placement}; },
      tile.image);
}

void check_tile(const TileImage& tile) {
  std::visit([&](const auto& image) { image_detail::check_image(image, tile.name); }, tile.image);
  if (const auto* rgba = std::get_if<Rgba8Image>(&tile.image); rgba && rgba->frames.size() != 1)
    throw ImageError(tile.name + ": a tile has one frame, this image has " +
                     std::to_string(rgba->frames.size()));
}

Rect rect_of(const TileExtent& tile) {
  const Placement p = placement_of(tile);
  return {p.x, p.x + tile.width, p.y, p.y + tile.height};
}

void check_overlaps(const std::vector<TileExtent>& tiles, const std::vector<Rect>& rects) {
  for (std::size_t i = 0; i < rects.size(); ++i)
    for (std::size_t j = i + 1; j < rects.size(); ++j) {
      const Rect shared{std::max(rects[i].x0, rects[j].x0), std::min(rects[i].x1, rects[j].x1),
                        std::max(rects[i].y0, rects[j].y0), std::min(rects[i].y1, rects[j].y1)};
      if (shared.x0 < shared.x1 && shared.y0 < shared.y1)
        throw ImageError("tiles " + tiles[i].name + " and " + tiles[j].name +
                         " overlap: both cover pixels " + rect_text(shared));
    }
}

// Without overlaps, the tiles cover the frame exactly when their areas add up to it. Otherwise
// the gaps are found on the grid of every tile edge: each cell of it is covered whole or not at
// all, so the uncovered cells, merged along rows, are the gaps.
void check_gaps(const std::vector<Rect>& rects, StitchedFrame frame) {
  std::int64_t covered = 0;
  for (const Rect& r : rects) covered += r.pixels();
  const std::int64_t all = std::int64_t{frame.width} * frame.height;
  if (covered == all) return;
  std::vector<int> xs{0, frame.width}, ys{0, frame.height};
  for (const Rect& r : rects) {
    xs.insert(xs.end(), {r.x0, r.x1});
    ys.insert(ys.end(), {r.y0, r.y1});
  }
  for (std::vector<int>* edges : {&xs, &ys}) {
    std::sort(edges->begin(), edges->end());
    edges->erase(std::unique(edges->begin(), edges->end()), edges->end());
  }
  const auto index = [](const std::vector<int>& edges, int at) {
    return static_cast<std::size_t>(std::lower_bound(edges.begin(), edges.end(), at) -
                                    edges.begin());
  };
  const std::size_t columns = xs.size() - 1;
  std::vector<bool> cell_covered(columns * (ys.size() - 1), false);
  for (const Rect& r : rects)
    for (std::size_t row = index(ys, r.y0); row < index(ys, r.y1); ++row)
      for (std::size_t column = index(xs, r.x0); column < index(xs, r.x1); ++column)
        cell_covered[row * columns + column] = true;
  std::vector<Rect> gaps;
  for (std::size_t row = 0; row + 1 < ys.size(); ++row)
    for (std::size_t column = 0; column < columns; ++column) {
      if (cell_covered[row * columns + column]) continue;
      const Rect cell{xs[column], xs[column + 1], ys[row], ys[row + 1]};
      if (!gaps.empty() && gaps.back().y0 == cell.y0 && gaps.back().x1 == cell.x0)
        gaps.back().x1 = cell.x1;
      else
        gaps.push_back(cell);
    }
  constexpr std::size_t kListed = 4;
  std::string listed;
  for (std::size_t i = 0; i < std::min(gaps.size(), kListed); ++i)
    listed += (i ? ", " : "") + rect_text(gaps[i]);
  if (gaps.size() > kListed) listed += " and " + std::to_string(gaps.size() - kListed) + " more";
  throw ImageError("the tiles leave " + std::to_string(all - covered) + " of the " +
                   std::to_string(frame.width) + "x" + std::to_string(frame.height) +
                   " frame's pixels uncovered: " + listed);
}

}  // namespace

StitchedFrame stitched_frame(const std::vector<TileExtent>& tiles) {
  if (tiles.empty()) throw ImageError("no tiles to stitch");
  const Placement first = placement_of(tiles.front());
  const StitchedFrame frame{first.full_width, first.full_height};
  for (const TileExtent& tile : tiles) {
    const Placement p = placement_of(tile);
    if (p.full_width != frame.width || p.full_height != frame.height)
      throw ImageError(tile.name + " belongs to a " + std::to_string(p.full_width) + "x" +
                       std::to_string(p.full_height) + " frame, " + tiles.front().name +
                       " to a " + std::to_string(frame.width) + "x" +
                       std::to_string(frame.height) + " one");
  }
  // The frame would be written, and then refused by every reader of clrt's, itself included.
  if (!image_detail::within_image_limits(frame.width, frame.height))
    throw ImageError("the tiles belong to a " + std::to_string(frame.width) + "x" +
                     std::to_string(frame.height) + " frame (" +
                     std::to_string(std::int64_t{frame.width} * frame.height) +
                     " pixels), beyond the " + std::to_string(image_detail::kMostSide) +
                     " pixels a side and " + std::to_string(image_detail::kMostPixels) +
                     " pixels clrt reads");
  std::vector<Rect> rects;
  for (const TileExtent& tile : tiles) rects.push_back(rect_of(tile));
  check_overlaps(tiles, rects);
  check_gaps(rects, frame);
  return frame;
}

namespace {

// Rows of `channels` samples per pixel from the tile into the frame.
template <typename Sample>
void copy_rows(const Sample* tile, const Rect& r, std::size_t channels, Sample* frame,
               int frame_width) {
  const std::size_t row = channels * static_cast<std::size_t>(r.x1 - r.x0);
  for (int y = r.y0; y < r.y1; ++y)
    std::memcpy(frame + channels * (static_cast<std::size_t>(y) * frame_width + r.x0),
                tile + row * static_cast<std::size_t>(y - r.y0), row * sizeof(Sample));
}

}  // namespace

AnyImage stitch_tiles(const std::vector<TileImage>& tiles) {
  std::vector<TileExtent> extents;
  for (const TileImage& tile : tiles) {
    check_tile(tile);
    extents.push_back(extent_of(tile));
  }
  const StitchedFrame frame = stitched_frame(extents);
  std::vector<Rect> rects;
  for (const TileExtent& extent : extents) rects.push_back(rect_of(extent));
  const std::size_t pixels = static_cast<std::size_t>(frame.width) * frame.height;
  const bool all_8bit = std::all_of(tiles.begin(), tiles.end(), [](const TileImage& tile) {
    return std::holds_alternative<Rgba8Image>(tile.image);
  });
  if (all_8bit) {
    Rgba8Image out(frame.width, frame.height, {std::vector<std::uint8_t>(4 * pixels)});
    for (std::size_t i = 0; i < tiles.size(); ++i)
      copy_rows(std::get<Rgba8Image>(tiles[i].image).frames.front().data(), rects[i], 4,
                out.frames.front().data(), frame.width);
    return out;
  }
  FloatImage out(frame.width, frame.height, std::vector<float>(3 * pixels));
  for (std::size_t i = 0; i < tiles.size(); ++i) {
    if (const auto* floats = std::get_if<FloatImage>(&tiles[i].image))
      copy_rows(floats->rgb.data(), rects[i], 3, out.rgb.data(), frame.width);
    else
      copy_rows(to_float(std::get<Rgba8Image>(tiles[i].image)).rgb.data(), rects[i], 3,
                out.rgb.data(), frame.width);
  }
  return out;
}

}  // namespace clrt

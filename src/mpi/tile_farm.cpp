#include "mpi/tile_farm.hpp"

#include <mpi.h>

#include <atomic>
#include <chrono>
#include <cstring>
#include <iostream>
#include <thread>

namespace clrt::mpi {
namespace {

enum Tag : int {
  kDone = 1,      // rank -> rank 0: a tile's pixels (or none yet), asking for the next
  kFailed = 2,    // rank -> rank 0: the rank's error message
  kAssigned = 3,  // rank 0 -> rank: the next tile (its index), or -1: no more
};

// The pixels of a rendered tile as bytes, 8-bit RGBA or float RGB, row by row.
const char* pixel_bytes(const AnyImage& image, std::size_t& size) {
  if (const auto* bytes = std::get_if<Rgba8Image>(&image)) {
    size = bytes->frames[0].size();
    return reinterpret_cast<const char*>(bytes->frames[0].data());
  }
  const FloatImage& floats = std::get<FloatImage>(image);
  size = floats.rgb.size() * sizeof(float);
  return reinterpret_cast<const char*>(floats.rgb.data());
}

// Copies a tile's pixels into the region's image.
void place(AnyImage& image, const PixelRect& region, const PixelRect& tile, const char* pixels) {
  const std::size_t pixel = std::holds_alternative<Rgba8Image>(image) ? 4 : 3 * sizeof(float);
  char* into = std::holds_alternative<Rgba8Image>(image)
                   ? reinterpret_cast<char*>(std::get<Rgba8Image>(image).frames[0].data())
                   : reinterpret_cast<char*>(std::get<FloatImage>(image).rgb.data());
  for (std::uint32_t row = 0; row < tile.height; ++row) {
    const std::size_t at = (std::size_t{tile.y - region.y + row} * region.width + (tile.x - region.x)) * pixel;
    std::memcpy(into + at, pixels + std::size_t{row} * tile.width * pixel, tile.width * pixel);
  }
}

AnyImage empty_image(const PixelRect& region, bool eight_bit) {
  const int w = static_cast<int>(region.width), h = static_cast<int>(region.height);
  if (eight_bit) {
    Rgba8Image image(w, h, std::vector<std::vector<std::uint8_t>>(1));
    image.frames[0].resize(4 * region.pixel_count());
    return image;
  }
  return FloatImage(w, h, std::vector<float>(3 * region.pixel_count()));
}

// Rank 0's thread that serves the other ranks until each has been told there is no more.
void deal(const Session& session, const std::vector<PixelRect>& tiles, std::atomic<std::size_t>& next,
          AnyImage& image, const PixelRect& region, FarmStats& stats, Progress& progress) {
  int working = session.size() - 1;
  std::vector<char> message;
  while (working > 0) {
    // MPI_Probe would spin a core at full speed, the core rank 0's renderer needs: look every
    // 200 us instead, far shorter than any tile takes.
    MPI_Status status;
    int arrived = 0;
    for (;;) {
      MPI_Iprobe(MPI_ANY_SOURCE, MPI_ANY_TAG, MPI_COMM_WORLD, &arrived, &status);
      if (arrived) break;
      std::this_thread::sleep_for(std::chrono::microseconds(200));
    }
    int length = 0;
    MPI_Get_count(&status, MPI_CHAR, &length);
    message.resize(static_cast<std::size_t>(length));
    MPI_Recv(message.data(), length, MPI_CHAR, status.MPI_SOURCE, status.MPI_TAG, MPI_COMM_WORLD,
             MPI_STATUS_IGNORE);
    const int from = status.MPI_SOURCE;
    if (status.MPI_TAG == kFailed) {
      progress.finish();
      std::cerr << std::string(message.begin(), message.end()) << "\n";
      session.abort(1);
    }
    std::int64_t done = -1;
    std::memcpy(&done, message.data(), sizeof done);
    if (done >= 0) {
      const PixelRect& tile = tiles[static_cast<std::size_t>(done)];
      place(image, region, tile, message.data() + sizeof done);
      stats.tiles[from] += 1;
      stats.pixels[from] += tile.pixel_count();
      stats.bytes[from] += static_cast<std::uint64_t>(length);
      progress.advance(tile.pixel_count());
    }
    const std::size_t k = next.fetch_add(1);
    const std::int64_t assigned = k < tiles.size() ? static_cast<std::int64_t>(k) : -1;
    MPI_Send(&assigned, 1, MPI_INT64_T, from, kAssigned, MPI_COMM_WORLD);
    if (assigned < 0) --working;
  }
}

void serve_rank_zero(const Session& session, Renderer& renderer, const PixelRect& region,
                     const std::vector<PixelRect>& tiles, bool eight_bit, AnyImage& image,
                     FarmStats& stats, Progress& progress) {
  std::atomic<std::size_t> next{0};
  std::thread dealer;
  if (session.size() > 1)
    dealer = std::thread(deal, std::cref(session), std::cref(tiles), std::ref(next),
                         std::ref(image), std::cref(region), std::ref(stats), std::ref(progress));
  try {
    for (std::size_t k; (k = next.fetch_add(1)) < tiles.size();) {
      const AnyImage tile = renderer.render(tiles[k], eight_bit);
      std::size_t size = 0;
      place(image, region, tiles[k], pixel_bytes(tile, size));
      stats.tiles[0] += 1;
      stats.pixels[0] += tiles[k].pixel_count();
      progress.advance(tiles[k].pixel_count());
    }
  } catch (const std::exception& e) {
    progress.finish();
    std::cerr << "clrt-mpi: error: rank 0: " << e.what() << "\n";
    session.abort(1);
  }
  if (dealer.joinable()) dealer.join();
}

void serve_other_rank(const Session& session, Renderer& renderer,
                      const std::vector<PixelRect>& tiles, bool eight_bit) {
  std::vector<char> message(sizeof(std::int64_t));
  std::int64_t done = -1;
  try {
    for (;;) {
      std::memcpy(message.data(), &done, sizeof done);
      MPI_Send(message.data(), static_cast<int>(message.size()), MPI_CHAR, 0, kDone,
               MPI_COMM_WORLD);
      MPI_Recv(&done, 1, MPI_INT64_T, 0, kAssigned, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
      if (done < 0) return;
      const AnyImage tile = renderer.render(tiles[static_cast<std::size_t>(done)], eight_bit);
      std::size_t size = 0;
      const char* pixels = pixel_bytes(tile, size);
      message.resize(sizeof done + size);
      std::memcpy(message.data() + sizeof done, pixels, size);
    }
  } catch (const std::exception& e) {
    const std::string text =
        "clrt-mpi: error: rank " + std::to_string(session.rank()) + ": " + e.what();
    MPI_Send(text.data(), static_cast<int>(text.size()), MPI_CHAR, 0, kFailed, MPI_COMM_WORLD);
    // Rank 0 ends the job; nothing more to do here.
    MPI_Recv(&done, 1, MPI_INT64_T, 0, kAssigned, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
  }
}

}  // namespace

std::vector<PixelRect> cut_into_tiles(const PixelRect& region, std::uint32_t width,
                                      std::uint32_t height) {
  std::vector<PixelRect> tiles;
  for (std::uint32_t y = 0; y < region.height; y += height)
    for (std::uint32_t x = 0; x < region.width; x += width)
      tiles.push_back({region.x + x, region.y + y, std::min(width, region.width - x),
                       std::min(height, region.height - y)});
  return tiles;
}

AnyImage farm_tiles(const Session& session, Renderer& renderer, const PixelRect& region,
                    const std::vector<PixelRect>& tiles, bool eight_bit, FarmStats& stats,
                    Progress& progress) {
  const auto ranks = static_cast<std::size_t>(session.size());
  stats.tiles.assign(ranks, 0);
  stats.pixels.assign(ranks, 0);
  stats.bytes.assign(ranks, 0);
  if (!session.first()) {
    serve_other_rank(session, renderer, tiles, eight_bit);
    return {};
  }
  AnyImage image = empty_image(region, eight_bit);
  serve_rank_zero(session, renderer, region, tiles, eight_bit, image, stats, progress);
  return image;
}

}  // namespace clrt::mpi

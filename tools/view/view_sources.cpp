#include <variant>

#include "view_sources.hpp"

#include <algorithm>

#include "image/compare.hpp"

namespace clrt::view {

int ViewSources::frame_count() const {
  return static_cast<int>(std::max(a.size(), b.size()));
}

const FloatImage& ViewSources::frame_of(const std::vector<FloatImage>& frames, int frame) {
  return frames[std::min<std::size_t>(static_cast<std::size_t>(frame), frames.size() - 1)];
}

std::vector<FloatImage> float_frames(const AnyImage& image) {
  if (const auto* floats = std::get_if<FloatImage>(&image)) return {*floats};
  const auto& rgba = std::get<Rgba8Image>(image);
  std::vector<FloatImage> frames;
  for (std::size_t f = 0; f < rgba.frames.size(); ++f) frames.push_back(to_float(rgba, f));
  return frames;
}

namespace {

// A one-frame image of frame `frame` (or the last), as compare_images takes it.
AnyImage one_frame(const AnyImage& image, int frame) {
  const auto* rgba = std::get_if<Rgba8Image>(&image);
  if (!rgba) return image;
  const int last = static_cast<int>(rgba->frames.size());
  return select_frame(*rgba, std::min(frame + 1, last));
}

}  // namespace

ViewSources make_sources(const AnyImage& a, const AnyImage* b) {
  ViewSources sources;
  sources.a = float_frames(a);
  sources.linear = std::holds_alternative<FloatImage>(a);
  sources.width = sources.a.front().width;
  sources.height = sources.a.front().height;
  if (!b) return sources;
  sources.b = float_frames(*b);
  if (sources.b.front().width != sources.width || sources.b.front().height != sources.height)
    throw ImageError("the images differ in size: " + std::to_string(sources.width) + "x" +
                     std::to_string(sources.height) + " against " +
                     std::to_string(sources.b.front().width) + "x" +
                     std::to_string(sources.b.front().height));
  for (int f = 0; f < sources.frame_count(); ++f)
    sources.difference.push_back(
        compare_images(one_frame(a, f), one_frame(*b, f), 0).difference);
  return sources;
}

}  // namespace clrt::view

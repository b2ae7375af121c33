// Each NFF file renders to the same bytes as its .ray twin.
#include <algorithm>
#include <catch2/catch.hpp>

#include "image/image.hpp"
#include "nff_twins.hpp"
#include "render_support.hpp"

using clrt::test::nff_twins;
using clrt::test::render_file;

namespace {

// Small, and not square, so the widened NFF angle is checked along a width unlike the height.
clrt::Rgba8Image render_small(const std::string& path) {
  return clrt::quantize(render_file(path, [](clrt::RenderOptions& o) {
    o.width = 48;
    o.height = 40;
  }));
}

bool uniform(const clrt::Rgba8Image& image) {
  const auto& pixels = image.frames.at(0);
  for (std::size_t i = 4; i < pixels.size(); i += 4)
    if (!std::equal(pixels.begin(), pixels.begin() + 4, pixels.begin() + i)) return false;
  return true;
}

}  // namespace

TEST_CASE("every NFF file renders to the same bytes as its .ray twin", "[scene][nff][render]") {
  for (const auto& twin : nff_twins()) {
    INFO(twin.nff);
    const clrt::Rgba8Image nff = render_small(twin.nff), ray = render_small(twin.ray);
    CHECK_FALSE(uniform(nff));
    CHECK(nff.frames == ray.frames);
  }
}

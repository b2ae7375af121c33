// The writers behind write_image. Each takes an image check_image has accepted.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "image/image.hpp"

namespace clrt::image_detail {

// All frames, streamed straight into an AtomicFile (an animation may be large).
void write_fsf(const std::string& path, const Rgba8Image& image);

// Frame 0 only, as whole files in memory.
std::vector<std::uint8_t> encode_png(const Rgba8Image& image);
std::vector<std::uint8_t> encode_ppm(const Rgba8Image& image);
std::vector<std::uint8_t> encode_pfm(const FloatImage& image);

}  // namespace clrt::image_detail

// Preconditions every writer and converter shares: a non-empty image whose pixel arrays match
// its size, and a placement inside its frame.
#pragma once

#include <string>

#include "image/image.hpp"

namespace clrt::image_detail {

// Throw ImageError("<context>: <what is wrong>").
void check_image(const FloatImage& image, const std::string& context);
void check_image(const Rgba8Image& image, const std::string& context);

}  // namespace clrt::image_detail

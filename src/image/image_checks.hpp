// Preconditions every writer and converter shares: a non-empty image whose pixel arrays match
// its size, and a placement inside its frame.
#pragma once

#include <cstdint>
#include <string>

#include "image/image.hpp"

namespace clrt::image_detail {

// Throw ImageError("<context>: <what is wrong>").
void check_image(const FloatImage& image, const std::string& context);
void check_image(const Rgba8Image& image, const std::string& context);

// What a header declares, before anything is allocated for it: beyond within_image_limits()
// throws ImageError("<path>: the <format>'s WxH pixels are more than clrt reads (...)"). Every
// reader refuses such an image, so none can be converted into a file that the readers refuse.
void check_declared_size(std::int64_t width, std::int64_t height, const std::string& path,
                         const std::string& format);

}  // namespace clrt::image_detail

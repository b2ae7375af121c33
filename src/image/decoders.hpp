// The readers behind read_image_info and read_any_image, one pair per format: the header alone,
// and the pixels (the public read_fsf, read_png, ... in image.hpp).
#pragma once

#include <string>

#include "image/image_info.hpp"

namespace clrt::image_detail {

ImageInfo fsf_info(const std::string& path);
ImageInfo png_info(const std::string& path);
ImageInfo ppm_info(const std::string& path);
ImageInfo pfm_info(const std::string& path);
ImageInfo exr_info(const std::string& path);

}  // namespace clrt::image_detail

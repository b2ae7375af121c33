// The readers behind read_image_info and read_any_image, one pair per format: the header alone,
// and the pixels (the public read_fsf, read_png, ... in image.hpp).
#pragma once

#include <string>

#include "image/image_info.hpp"

namespace clrt::image_detail {

// What every format's info holds: one frame, no placement, no details yet.
ImageInfo basic_info(ImageFormat format, int width, int height, std::string channels,
                     std::string samples);

ImageInfo fsf_info(const std::string& path);
ImageInfo png_info(const std::string& path);
ImageInfo ppm_info(const std::string& path);
ImageInfo pfm_info(const std::string& path);
ImageInfo exr_info(const std::string& path);

}  // namespace clrt::image_detail

// The readers behind decode_image and decode_image_info, one pair per format: the header alone,
// and the pixels, both from the file's bytes in memory (the public read_png, ... in image.hpp
// read the file first). Their messages name `file.name`.
#pragma once

#include <string>

#include "image/byte_span.hpp"
#include "image/image_info.hpp"

namespace clrt::image_detail {

// What every format's info holds: one frame, no placement, no details yet.
ImageInfo basic_info(ImageFormat format, int width, int height, std::string channels,
                     std::string samples);

ImageInfo fsf_info(const ImageBytes& file);
ImageInfo png_info(const ImageBytes& file);
ImageInfo ppm_info(const ImageBytes& file);
ImageInfo pfm_info(const ImageBytes& file);
ImageInfo exr_info(const ImageBytes& file);

Rgba8Image fsf_pixels(const ImageBytes& file, Frames frames);
Rgba8Image png_pixels(const ImageBytes& file);
Rgba8Image ppm_pixels(const ImageBytes& file);
FloatImage pfm_pixels(const ImageBytes& file);
FloatImage exr_pixels(const ImageBytes& file);

}  // namespace clrt::image_detail

// The writers behind write_image, each streaming into a ByteSink. Each takes an image
// check_image has accepted.
#pragma once

#include "image/byte_sink.hpp"
#include "image/eight_bit_rows.hpp"
#include "image/image.hpp"

namespace clrt::image_detail {

void encode_fsf(const EightBitRows& rows, ByteSink& sink);  // every frame
// The pieces of an FSF file, for an animation written frame by frame (fsf_animation.hpp).
void write_fsf_header(int width, int height, std::size_t frames, ByteSink& sink);
void write_fsf_frame(const EightBitRows& rows, std::size_t frame, ByteSink& sink);
// Frame 0, the placement and, unless empty, `samples` (WriteOptions::samples).
void encode_png(const EightBitRows& rows, const PngEncoding& encoding, ByteSink& sink,
                const std::string& samples = {});
// ImageError for an encoding zlib cannot take; called before any output exists.
void check_png_encoding(const PngEncoding& encoding);
void encode_ppm(const EightBitRows& rows, ByteSink& sink);  // frame 0
void encode_pfm(const FloatImage& image, ByteSink& sink);
// Where an encoder says what its format could not hold (WriteOptions::warn).
using Warn = std::function<void(const std::string&)>;
// And the placement and, unless empty, `samples` (WriteOptions::samples).
void encode_exr(const FloatImage& image, ExrPixel pixel, const Warn& warn, ByteSink& sink,
                const std::string& samples = {});

}  // namespace clrt::image_detail

// GIF output for sharing an animation (`clrt-img convert turn.fsf turn.gif`): every frame of an
// 8-bit image, looping, each shown for `delay_cs` hundredths of a second.
//
// GIF holds at most 256 colours a frame. The palette is fixed, 6 levels of red, 7 of green and
// 6 of blue (252 colours, green finest as the eye is most sensitive to it), and each pixel is
// ordered-dithered onto it with an 8x8 Bayer matrix. A fixed palette gives the same bytes for
// the same frames whatever the rest of the animation holds, keeps colours still from frame to
// frame (an adaptive palette per frame makes flat areas flicker), and a colour that lies on the
// palette (black, white, the primaries) comes out exact.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "image/byte_sink.hpp"
#include "image/image.hpp"

namespace clrt::img {

// The palette's levels per channel, and its colour for an index.
constexpr int kGifLevels[3] = {6, 7, 6};
std::uint8_t gif_level_value(int channel, int level);

// The palette index of pixel (x, y) of colour `rgb`, dithered by its place.
std::uint8_t gif_palette_index(const std::uint8_t rgb[3], int x, int y);

// The whole file, written to `sink` piece by piece as giflib makes it (a GIF of millions of
// frames is never held whole); ImageError if giflib fails, or the sink's own error.
void encode_gif(const Rgba8Image& image, int delay_cs, image_detail::ByteSink& sink);

// Written to a temporary and renamed into place, as every image clrt writes.
void write_gif(const std::string& path, const Rgba8Image& image, int delay_cs);

// Whether a name asks for GIF (case-insensitive .gif).
bool is_gif_path(const std::string& path);

}  // namespace clrt::img

// PNG through libpng's full API (the simplified one cannot read text chunks). Every colour type
// and bit depth becomes 8-bit RGBA: palettes and transparency expanded, 16-bit samples rounded
// (round(v * 255 / 65535)), grey copied to R, G and B. Samples are taken as they are, with no
// gamma or ICC conversion: clrt treats them as plain display values. CRC errors in any chunk
// are errors, so a damaged placement chunk is never silently dropped.
#include <png.h>

#include <cstdint>
#include <cstring>
#include <new>

#include "image/decoders.hpp"
#include "image/image_checks.hpp"
#include "image/image_limits.hpp"
#include "image/placement.hpp"
#include "image/png_errors.hpp"

namespace clrt {
namespace {

using image_detail::PngErrors;
using image_detail::png_guarded;

struct PngInput {
  PngErrors errors;
  ByteSpan bytes;
  std::size_t position = 0;
};

void read_from_memory(png_structp png, png_bytep out, std::size_t size) {
  auto* input = static_cast<PngInput*>(png_get_io_ptr(png));
  if (size > input->bytes.size() - input->position) png_error(png, "the file ended early");
  std::memcpy(out, input->bytes.data() + input->position, size);
  input->position += size;
}

// libpng allocates a chunk's declared length before reading it, so a forged length (a 45-byte
// file declaring 1.3 GB) would cost that much memory: every chunk must fit in the file first.
void check_chunk_lengths(ByteSpan bytes) {
  constexpr std::size_t kSignature = 8, kFraming = 12;  // length, type, CRC
  for (std::size_t at = kSignature; at + kFraming <= bytes.size();) {
    const std::uint64_t length = std::uint64_t{bytes[at]} << 24 | std::uint64_t{bytes[at + 1]} << 16 |
                                 std::uint64_t{bytes[at + 2]} << 8 | bytes[at + 3];
    if (length > bytes.size() - at - kFraming)
      throw ImageError("a chunk declares " + std::to_string(length) +
                       " bytes, more than the file has left");
    if (std::memcmp(bytes.data() + at + 4, "IEND", 4) == 0) return;
    at += kFraming + length;
  }
}

class PngReadStructs {
 public:
  explicit PngReadStructs(PngErrors& errors)
      : png_(png_create_read_struct(PNG_LIBPNG_VER_STRING, &errors, image_detail::png_record_error,
                                    image_detail::png_ignore_warning)),
        info_(png_ ? png_create_info_struct(png_) : nullptr) {
    if (!info_) throw ImageError("libpng could not allocate its state");
  }
  ~PngReadStructs() { png_destroy_read_struct(&png_, &info_, nullptr); }
  PngReadStructs(const PngReadStructs&) = delete;
  PngReadStructs& operator=(const PngReadStructs&) = delete;

  png_structp png() const { return png_; }
  png_infop info() const { return info_; }

 private:
  png_structp png_;
  png_infop info_;
};

std::string colour_type_name(int colour_type, bool transparency) {
  const std::string with = transparency ? " with transparency (tRNS)" : "";
  switch (colour_type) {
    case PNG_COLOR_TYPE_GRAY:
      return "grey" + with;
    case PNG_COLOR_TYPE_PALETTE:
      return "palette" + with;
    case PNG_COLOR_TYPE_RGB:
      return "RGB" + with;
    case PNG_COLOR_TYPE_GRAY_ALPHA:
      return "grey, alpha";
    default:
      return "RGBA";
  }
}

// A PNG opened up to its image data: the header and the text chunks before it.
class PngDecoder {
 public:
  explicit PngDecoder(const ImageBytes& file)
      : path_(file.name), input_{{}, file.bytes}, structs_(input_.errors) {
    try {
      check_chunk_lengths(file.bytes);
    } catch (const ImageError& e) {
      throw ImageError(path_ + ": not a readable PNG: " + e.what());
    }
    png_structp png = structs_.png();
    png_infop info = structs_.info();
    png_textp texts = nullptr;
    int text_count = 0;
    const bool ok = png_guarded(png, [&] {
      png_set_read_fn(png, &input_, read_from_memory);
      png_set_crc_action(png, PNG_CRC_ERROR_QUIT, PNG_CRC_ERROR_QUIT);
      // The sides clrt renders: a forged IHDR in a file of a few bytes would otherwise have the
      // image allocated (and zeroed) at whatever size it names before any pixel is decoded.
      png_set_user_limits(png, image_detail::kMostSide, image_detail::kMostSide);
      png_read_info(png, info);
      png_get_IHDR(png, info, &width_, &height_, &bit_depth_, &colour_type_, &interlace_, nullptr,
                   nullptr);
      valid_ = png_get_valid(png, info, PNG_INFO_tRNS | PNG_INFO_sRGB | PNG_INFO_gAMA |
                                            PNG_INFO_iCCP);
      png_get_text(png, info, &texts, &text_count);
    });
    if (!ok) fail();
    image_detail::check_declared_size(width_, height_, path_, "PNG");
    for (int i = 0; i < text_count; ++i) {
      if (std::strcmp(texts[i].key, image_detail::kPngPlacementKey) != 0) continue;
      const std::string context =
          path_ + ": the " + image_detail::kPngPlacementKey + " text chunk";
      if (placement_) throw ImageError(context + " appears twice");
      placement_ = image_detail::parse_placement_text(
          std::string(texts[i].text, texts[i].text_length), width(), height(), context);
    }
    placement_ = image_detail::recorded_placement(placement_, width(), height());
  }

  int width() const { return static_cast<int>(width_); }
  int height() const { return static_cast<int>(height_); }

  ImageInfo info() const {
    ImageInfo info = image_detail::basic_info(
        ImageFormat::Png, width(), height(), colour_type_name(colour_type_, valid_ & PNG_INFO_tRNS),
        std::to_string(bit_depth_) + "-bit" +
            (colour_type_ == PNG_COLOR_TYPE_PALETTE ? " indices" : ""));
    info.placement = placement_;
    info.details = {{"interlace", interlace_ == PNG_INTERLACE_NONE ? "none" : "Adam7"},
                    {"colour space", colour_space()}};
    return info;
  }

  Rgba8Image pixels() {
    png_structp png = structs_.png();
    png_infop info = structs_.info();
    std::size_t row_bytes = 0;
    bool ok = png_guarded(png, [&] {
      png_set_expand(png);
      png_set_scale_16(png);
      png_set_gray_to_rgb(png);
      png_set_add_alpha(png, 0xff, PNG_FILLER_AFTER);
      png_set_interlace_handling(png);
      png_read_update_info(png, info);
      row_bytes = png_get_rowbytes(png, info);
    });
    if (!ok) fail();
    const std::size_t width = width_, height = height_;
    if (row_bytes != 4 * width)
      throw ImageError(path_ + ": libpng made rows of " + std::to_string(row_bytes) +
                       " bytes, not the 4 * width of 8-bit RGBA");
    std::vector<std::uint8_t> rgba;
    std::vector<png_bytep> rows;
    try {
      rgba.resize(row_bytes * height);
      rows.resize(height);
    } catch (const std::bad_alloc&) {
      throw ImageError(path_ + ": not enough memory for a " + std::to_string(width) + "x" +
                       std::to_string(height) + " PNG");
    }
    for (std::size_t y = 0; y < height; ++y) rows[y] = rgba.data() + y * row_bytes;
    png_bytepp row_pointers = rows.data();
    ok = png_guarded(png, [&] {
      png_read_image(png, row_pointers);
      png_read_end(png, nullptr);
    });
    if (!ok) fail();
    return Rgba8Image(this->width(), this->height(), {std::move(rgba)}, placement_);
  }

 private:
  [[noreturn]] void fail() const {
    image_detail::throw_png_failure(input_.errors, path_ + ": not a readable PNG: ");
  }

  std::string colour_space() const {
    if (valid_ & PNG_INFO_sRGB) return "sRGB";
    if (valid_ & PNG_INFO_iCCP) return "ICC profile";
    if (valid_ & PNG_INFO_gAMA) return "gamma only";
    return "unspecified";
  }

  std::string path_;
  PngInput input_;
  PngReadStructs structs_;
  png_uint_32 width_ = 0, height_ = 0, valid_ = 0;
  int bit_depth_ = 0, colour_type_ = 0, interlace_ = 0;
  std::optional<Placement> placement_;
};

}  // namespace

Rgba8Image image_detail::png_pixels(const ImageBytes& file) { return PngDecoder(file).pixels(); }

ImageInfo image_detail::png_info(const ImageBytes& file) { return PngDecoder(file).info(); }

}  // namespace clrt

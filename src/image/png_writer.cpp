// PNG through libpng's full API (the simplified one cannot write text chunks): rows are
// quantised one at a time and the encoded bytes stream into the sink as libpng produces them.
#include <png.h>
#include <zlib.h>

#include <vector>

#include "image/encoders.hpp"
#include "image/placement.hpp"
#include "image/png_errors.hpp"

namespace clrt::image_detail {
namespace {

struct PngOutput {
  PngErrors errors;
  ByteSink* sink;
};

void write_to_sink(png_structp png, png_bytep data, std::size_t size) {
  auto* output = static_cast<PngOutput*>(png_get_io_ptr(png));
  bool failed = false;
  try {
    output->sink->write(data, size);
  } catch (...) {
    output->errors.failure = std::current_exception();
    failed = true;
  }
  if (failed) png_error(png, "the output failed");
}

void flush_nothing(png_structp) {}

class PngWriteStructs {
 public:
  explicit PngWriteStructs(PngErrors& errors)
      : png_(png_create_write_struct(PNG_LIBPNG_VER_STRING, &errors, png_record_error,
                                     png_ignore_warning)),
        info_(png_ ? png_create_info_struct(png_) : nullptr) {
    if (!info_) throw ImageError("PNG encoding failed: libpng could not allocate its state");
  }
  ~PngWriteStructs() { png_destroy_write_struct(&png_, &info_); }
  PngWriteStructs(const PngWriteStructs&) = delete;
  PngWriteStructs& operator=(const PngWriteStructs&) = delete;

  png_structp png() const { return png_; }
  png_infop info() const { return info_; }

 private:
  png_structp png_;
  png_infop info_;
};

int filter_mask(PngFilters filters) {
  switch (filters) {
    case PngFilters::None: return PNG_FILTER_NONE;
    case PngFilters::Sub: return PNG_FILTER_SUB;
    case PngFilters::Up: return PNG_FILTER_UP;
    case PngFilters::Average: return PNG_FILTER_AVG;
    case PngFilters::Paeth: return PNG_FILTER_PAETH;
    case PngFilters::Adaptive: return PNG_ALL_FILTERS;
  }
  return PNG_ALL_FILTERS;
}

int zlib_strategy(PngStrategy strategy) {
  switch (strategy) {
    case PngStrategy::Default: return Z_DEFAULT_STRATEGY;
    case PngStrategy::Filtered: return Z_FILTERED;
    case PngStrategy::Rle: return Z_RLE;
    case PngStrategy::HuffmanOnly: return Z_HUFFMAN_ONLY;
  }
  return Z_DEFAULT_STRATEGY;
}

// libpng's compressed-data buffer, hence the size of each IDAT chunk: large enough that the
// chunks pass the sink's gathering buffer straight to the output (libpng's default is 8 KiB).
constexpr std::size_t kIdatBytes = std::size_t{1} << 17;

}  // namespace

void check_png_encoding(const PngEncoding& encoding) {
  if (encoding.level < 0 || encoding.level > 9)
    throw ImageError("PNG compression level " + std::to_string(encoding.level) +
                     " is outside 0-9");
}

// An opaque frame (everything clrt renders) is stored as RGB: a quarter smaller, same pixels.
// The sRGB chunk says the samples are display values, as the contract's quantisation makes them.
void encode_png(const EightBitRows& rows, const PngEncoding& encoding, ByteSink& sink) {
  PngOutput output{{}, &sink};
  const PngWriteStructs structs(output.errors);
  png_structp png = structs.png();
  png_infop info = structs.info();
  const bool opaque = rows.opaque();
  const auto placement = recorded_placement(rows.placement(), rows.width(), rows.height());
  std::string placement_value =
      placement ? placement_text(*placement, rows.width(), rows.height()) : "";
  std::string key = kPngPlacementKey;
  png_text text{};
  text.compression = PNG_TEXT_COMPRESSION_NONE;
  text.key = key.data();
  text.text = placement_value.data();
  text.text_length = placement_value.size();
  std::vector<std::uint8_t> scratch(4 * static_cast<std::size_t>(rows.width()));
  std::uint8_t* row = scratch.data();

  const bool ok = png_guarded(png, [&] {
    png_set_write_fn(png, &output, write_to_sink, flush_nothing);
    png_set_IHDR(png, info, static_cast<png_uint_32>(rows.width()),
                 static_cast<png_uint_32>(rows.height()), 8,
                 opaque ? PNG_COLOR_TYPE_RGB : PNG_COLOR_TYPE_RGBA, PNG_INTERLACE_NONE,
                 PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
    png_set_compression_level(png, encoding.level);
    png_set_compression_strategy(png, zlib_strategy(encoding.strategy));
    png_set_filter(png, PNG_FILTER_TYPE_BASE, filter_mask(encoding.filters));
    png_set_compression_buffer_size(png, kIdatBytes);
    png_set_sRGB(png, info, PNG_sRGB_INTENT_PERCEPTUAL);
    if (placement) png_set_text(png, info, &text, 1);
    png_write_info(png, info);
    for (int y = 0; y < rows.height(); ++y)
      png_write_row(png, opaque ? rows.rgb_row(0, y, row) : rows.rgba_row(0, y, row));
    png_write_end(png, nullptr);
  });
  if (!ok) throw_png_failure(output.errors, "PNG encoding failed: ");
}

}  // namespace clrt::image_detail

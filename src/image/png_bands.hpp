// PNG's image data, the zlib stream of the filtered rows, compressed on every core: the rows are
// cut into bands, each band is filtered and deflated on its own (ending on a byte boundary with
// a sync flush, the last one with the final block), and the pieces joined in order form one
// valid stream, the Adler-32 checksums combined. This is how pigz parallelises gzip.
#pragma once

#include <cstddef>
#include <cstdint>
#include <functional>

#include "image/eight_bit_rows.hpp"
#include "image/png_encoding.hpp"

namespace clrt::image_detail {

// Calls `emit` on the calling thread with each piece of the stream, in order (the first holds
// zlib's header, the last its checksum); the pieces joined are the whole stream. Frame 0 of
// `rows`, as RGBA (4 bytes a pixel) or RGB. The bands depend only on the image's size, never on
// the number of cores, so the bytes are the same on every machine. Exceptions from `emit` or
// from a band's compression reach the caller after every worker has stopped.
void compress_png_rows(const EightBitRows& rows, bool rgba, const PngEncoding& encoding,
                       const std::function<void(const std::uint8_t*, std::size_t)>& emit);

}  // namespace clrt::image_detail

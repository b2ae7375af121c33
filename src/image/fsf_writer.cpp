#include <limits>
#include <vector>

#include "image/byte_order.hpp"
#include "image/encoders.hpp"
#include "image/fsf_layout.hpp"

namespace clrt::image_detail {

void write_fsf_header(int width, int height, std::size_t frames, ByteSink& sink) {
  if (frames > std::numeric_limits<std::uint32_t>::max())
    throw ImageError("FSF holds at most 2^32 - 1 frames");
  std::vector<std::uint8_t> header;
  for (std::uint32_t field : {kFsfMagic, static_cast<std::uint32_t>(width),
                              static_cast<std::uint32_t>(height), static_cast<std::uint32_t>(frames)})
    append_u32_le(header, field);
  sink.write(header.data(), header.size());
}

void write_fsf_frame(const EightBitRows& rows, std::size_t frame, ByteSink& sink) {
  std::vector<std::uint8_t> scratch(4 * static_cast<std::size_t>(rows.width()));
  for (int y = 0; y < rows.height(); ++y)
    sink.write(rows.rgba_row(frame, y, scratch.data()), scratch.size());
}

void encode_fsf(const EightBitRows& rows, ByteSink& sink) {
  write_fsf_header(rows.width(), rows.height(), rows.frames(), sink);
  for (std::size_t frame = 0; frame < rows.frames(); ++frame) write_fsf_frame(rows, frame, sink);
}

}  // namespace clrt::image_detail

#include <limits>
#include <vector>

#include "image/byte_order.hpp"
#include "image/encoders.hpp"
#include "image/fsf_layout.hpp"

namespace clrt::image_detail {

void encode_fsf(const EightBitRows& rows, ByteSink& sink) {
  if (rows.frames() > std::numeric_limits<std::uint32_t>::max())
    throw ImageError("FSF holds at most 2^32 - 1 frames");
  std::vector<std::uint8_t> header;
  for (std::uint32_t field :
       {kFsfMagic, static_cast<std::uint32_t>(rows.width()),
        static_cast<std::uint32_t>(rows.height()), static_cast<std::uint32_t>(rows.frames())})
    append_u32_le(header, field);
  sink.write(header.data(), header.size());
  std::vector<std::uint8_t> scratch(4 * static_cast<std::size_t>(rows.width()));
  for (std::size_t frame = 0; frame < rows.frames(); ++frame)
    for (int y = 0; y < rows.height(); ++y)
      sink.write(rows.rgba_row(frame, y, scratch.data()), scratch.size());
}

}  // namespace clrt::image_detail

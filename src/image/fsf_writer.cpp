#include <limits>

#include "image/atomic_file.hpp"
#include "image/byte_order.hpp"
#include "image/encoders.hpp"
#include "image/fsf_layout.hpp"

namespace clrt::image_detail {

void write_fsf(const std::string& path, const Rgba8Image& image) {
  if (image.frames.size() > std::numeric_limits<std::uint32_t>::max())
    throw ImageError("cannot write " + path + ": FSF holds at most 2^32 - 1 frames");
  std::vector<std::uint8_t> header;
  for (std::uint32_t field :
       {kFsfMagic, static_cast<std::uint32_t>(image.width),
        static_cast<std::uint32_t>(image.height), static_cast<std::uint32_t>(image.frames.size())})
    append_u32_le(header, field);
  AtomicFile file(path);
  file.write(header.data(), header.size());
  for (const std::vector<std::uint8_t>& frame : image.frames)
    file.write(frame.data(), frame.size());
  file.commit();
}

}  // namespace clrt::image_detail

#include "image/exr_streams.hpp"

#include <OpenEXR/Iex.h>

#include <cstring>

namespace clrt::image_detail {

void MemoryOStream::write(const char c[], int n) {
  const std::size_t size = static_cast<std::size_t>(n);
  const std::size_t end = static_cast<std::size_t>(position_) + size;
  if (end > bytes_.size()) bytes_.resize(end);
  std::memcpy(bytes_.data() + position_, c, size);
  position_ = end;
}

bool MemoryIStream::read(char c[], int n) {
  const std::size_t size = static_cast<std::size_t>(n);
  if (position_ > bytes_.size() || size > bytes_.size() - position_)
    throw Iex::InputExc("the file ended early");
  std::memcpy(c, bytes_.data() + position_, size);
  position_ += size;
  return position_ < bytes_.size();
}

}  // namespace clrt::image_detail

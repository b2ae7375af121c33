#include "image/byte_sink.hpp"

#include <unistd.h>

#include <cerrno>
#include <cstring>

#include "image/sink_error.hpp"

namespace clrt::image_detail {
namespace {

constexpr std::size_t kBlockBytes = std::size_t{1} << 16;

}  // namespace

void ByteSink::write(const void* data, std::size_t size) {
  if (buffer_.size() + size > kBlockBytes) flush();
  if (size >= kBlockBytes) return write_through(data, size);
  const auto* bytes = static_cast<const std::uint8_t*>(data);
  buffer_.insert(buffer_.end(), bytes, bytes + size);
}

void ByteSink::flush() {
  if (buffer_.empty()) return;
  write_through(buffer_.data(), buffer_.size());
  buffer_.clear();
}

FdSink::~FdSink() {
  if (owned_ && fd_ >= 0) ::close(fd_);
}

void FdSink::finish() {
  flush();
  if (!owned_) return;
  const int fd = fd_;
  fd_ = -1;
  if (::close(fd) != 0) fail(errno);
}

void FdSink::write_through(const void* data, std::size_t size) {
  if (const int error = write_all(fd_, data, size)) fail(error);
}

void FdSink::fail(int error) const {
  throw SinkError("cannot write " + name_ + ": " + std::strerror(error));
}

int write_all(int fd, const void* data, std::size_t size) {
  const auto* bytes = static_cast<const char*>(data);
  while (size > 0) {
    const ssize_t written = ::write(fd, bytes, size);
    if (written < 0) {
      if (errno == EINTR) continue;
      return errno;
    }
    bytes += written;
    size -= static_cast<std::size_t>(written);
  }
  return 0;
}

}  // namespace clrt::image_detail

#include "preview_feed.hpp"

#include <sys/socket.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <vector>

#include "image/preview_stream.hpp"

namespace clrt::view {
namespace {

// False at the end of the stream (or an error: clrt is gone either way).
bool read_exact(int fd, void* data, std::size_t size) {
  auto* bytes = static_cast<char*>(data);
  while (size > 0) {
    const ssize_t got = read(fd, bytes, size);
    if (got < 0 && errno == EINTR) continue;
    if (got <= 0) return false;
    bytes += got;
    size -= static_cast<std::size_t>(got);
  }
  return true;
}

}  // namespace

PreviewFeed::PreviewFeed(int fd) : fd_(fd) {
  PreviewHeader header{};
  if (!read_exact(fd_, &header, sizeof header) ||
      std::memcmp(header.magic, kPreviewMagic, sizeof kPreviewMagic) != 0)
    throw ImageError("--preview: standard input is not a preview stream from clrt --preview");
  if (header.width == 0 || header.height == 0 || header.width > 65536 || header.height > 65536)
    throw ImageError("--preview: the stream's image size is out of range");
  width_ = static_cast<int>(header.width);
  height_ = static_cast<int>(header.height);
  image_ = FloatImage(width_, height_, std::vector<float>(3 * std::size_t(width_) * height_));
  reader_ = std::thread([this] { read_bands(); });
}

PreviewFeed::~PreviewFeed() {
  // Unblocks the reader's read, then waits for it.
  shutdown(fd_, SHUT_RDWR);
  reader_.join();
}

void PreviewFeed::send_ready() {
  const char ready = kPreviewReady;
  // Nobody to tell when clrt is already gone.
  if (send(fd_, &ready, 1, MSG_NOSIGNAL) != 1) ended_ = true;
}

void PreviewFeed::read_bands() {
  const std::uint64_t pixels = std::uint64_t(width_) * std::uint64_t(height_);
  std::vector<float> band;
  PreviewBand head{};
  while (read_exact(fd_, &head, sizeof head)) {
    if (head.first > pixels || head.count > pixels - head.first) break;
    band.resize(3 * std::size_t{head.count});
    if (!read_exact(fd_, band.data(), band.size() * sizeof(float))) break;
    std::lock_guard<std::mutex> lock(mutex_);
    std::copy(band.begin(), band.end(), image_.rgb.begin() + std::ptrdiff_t(3 * head.first));
    fresh_ = true;
  }
  ended_ = true;
}

bool PreviewFeed::take(FloatImage& image) {
  std::lock_guard<std::mutex> lock(mutex_);
  if (!fresh_) return false;
  image = image_;
  fresh_ = false;
  return true;
}

}  // namespace clrt::view

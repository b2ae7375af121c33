// The viewer's side of `clrt --preview` (src/image/preview_stream.hpp): a thread reads the
// stream from a descriptor into an image that the window shows as it fills in.
#pragma once

#include <atomic>
#include <mutex>
#include <thread>

#include "image/image.hpp"

namespace clrt::view {

class PreviewFeed {
 public:
  // Reads the header (ImageError if it is not one); the bands come on a thread of their own.
  explicit PreviewFeed(int fd);
  ~PreviewFeed();
  PreviewFeed(const PreviewFeed&) = delete;
  PreviewFeed& operator=(const PreviewFeed&) = delete;

  int width() const { return width_; }
  int height() const { return height_; }
  // Tells clrt the window is open.
  void send_ready();
  // Copies the pixels into `image` when bands arrived since the last call; true if so.
  bool take(FloatImage& image);
  // The stream ended: the render is complete (or clrt stopped).
  bool ended() const { return ended_; }

 private:
  void read_bands();

  int fd_;
  int width_ = 0, height_ = 0;
  std::mutex mutex_;
  FloatImage image_;
  bool fresh_ = false;
  std::atomic<bool> ended_{false};
  std::thread reader_;
};

}  // namespace clrt::view

// clrt --preview: a clrt-view window (tools/view/) showing the render as it fills in. clrt never
// links SDL: it starts the clrt-view found beside its own executable and streams every finished
// band to it (src/image/preview_stream.hpp). The image written is the same with or without it.
#pragma once

#include <sys/types.h>

#include <condition_variable>
#include <cstdint>
#include <deque>
#include <memory>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

#include "image/display_transform.hpp"
#include "render/pixel_store.hpp"

namespace clrt {

// Every wait on the viewer is bounded, so that a viewer that never answers (a display that
// accepts the connection and stalls) or stops reading (stopped, swapped out) never holds the
// render: bands it cannot take in time are dropped, not waited for.
class PreviewWindow final : public PixelStore {
 public:
  // Starts clrt-view and waits, at most kReadyTimeoutMs, until its window is open; it shows the
  // pixels through `display`, as the 8-bit file is written. Nothing when that fails: `why` then
  // says what happened (no clrt-view beside clrt, no display, no answer), the viewer is ended
  // (SIGTERM, then SIGKILL after kEndGraceMs), and the render goes on without.
  static std::unique_ptr<PreviewWindow> open(std::uint32_t width, std::uint32_t height,
                                             const DisplayTransform& display, std::string& why);
  // Ends the stream, waiting at most kEndGraceMs for the viewer to take what is queued; the
  // window stays open for the user.
  ~PreviewWindow() override;
  PreviewWindow(const PreviewWindow&) = delete;
  PreviewWindow& operator=(const PreviewWindow&) = delete;

  // Queues the band for the sender and returns at once; once the window is closed, or when the
  // viewer has not taken kMaxQueuedBytes already queued, the band is dropped.
  void store(std::uint64_t first, std::uint32_t count, const dev::f4* pixels) override;
  // Bands dropped so far because the viewer was not taking them.
  std::uint64_t bands_dropped();

  static constexpr int kReadyTimeoutMs = 20000;
  static constexpr int kEndGraceMs = 2000;
  static constexpr std::size_t kMaxQueuedBytes = std::size_t{16} << 20;

 private:
  explicit PreviewWindow(int socket);
  void send_queued();

  int socket_;
  std::mutex mutex_;
  std::condition_variable changed_;
  std::deque<std::vector<char>> queue_;  // whole messages: a PreviewBand and its floats
  std::size_t queued_bytes_ = 0;
  bool sending_ = false, ending_ = false, closed_ = false;
  std::uint64_t dropped_ = 0;
  std::thread sender_;
};

// The clrt-view beside the running executable (as the build tree and an install place it).
std::string viewer_path();

}  // namespace clrt

// clrt --preview: a clrt-view window (tools/view/) showing the render as it fills in. clrt never
// links SDL: it starts the clrt-view found beside its own executable and streams every finished
// band to it (src/image/preview_stream.hpp). The image written is the same with or without it.
#pragma once

#include <sys/types.h>

#include <memory>
#include <mutex>
#include <string>

#include "image/display_transform.hpp"
#include "render/pixel_store.hpp"

namespace clrt {

class PreviewWindow final : public PixelStore {
 public:
  // Starts clrt-view and waits until its window is open; it shows the pixels through `display`,
  // as the 8-bit file is written. Nothing when that fails: `why` then says what happened (no
  // clrt-view beside clrt, no display), and the render goes on without.
  static std::unique_ptr<PreviewWindow> open(std::uint32_t width, std::uint32_t height,
                                             const DisplayTransform& display, std::string& why);
  ~PreviewWindow() override;  // ends the stream; the window stays open for the user
  PreviewWindow(const PreviewWindow&) = delete;
  PreviewWindow& operator=(const PreviewWindow&) = delete;

  // Sends the band; once the window is closed, sends nothing more.
  void store(std::uint64_t first, std::uint32_t count, const dev::f4* pixels) override;

 private:
  explicit PreviewWindow(int socket) : socket_(socket) {}
  bool send_all(const void* data, std::size_t size);

  int socket_;
  bool closed_ = false;
  std::mutex mutex_;
};

// The clrt-view beside the running executable (as the build tree and an install place it).
std::string viewer_path();

}  // namespace clrt

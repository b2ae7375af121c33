#include "cli/preview_window.hpp"

#include <fcntl.h>
#include <poll.h>
#include <spawn.h>
#include <sys/socket.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <vector>

#include "image/preview_stream.hpp"

extern char** environ;

namespace clrt {
namespace {

// Long enough for a window to open on a loaded machine; a viewer that never answers is given up.
constexpr int kReadyTimeoutMs = 20000;

}  // namespace

std::string viewer_path() {
  std::error_code error;
  const std::filesystem::path self = std::filesystem::read_symlink("/proc/self/exe", error);
  return (error ? std::filesystem::path("clrt-view") : self.parent_path() / "clrt-view").string();
}

std::unique_ptr<PreviewWindow> PreviewWindow::open(std::uint32_t width, std::uint32_t height,
                                                   const DisplayTransform& display,
                                                   std::string& why) {
  const std::string viewer = viewer_path();
  if (access(viewer.c_str(), X_OK) != 0) {
    why = "no clrt-view beside clrt (" + viewer + "; it is built where SDL2 is installed)";
    return nullptr;
  }
  int ends[2];
  if (socketpair(AF_UNIX, SOCK_STREAM | SOCK_CLOEXEC, 0, ends) != 0) {
    why = std::string("cannot make a socket for clrt-view: ") + std::strerror(errno);
    return nullptr;
  }
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_adddup2(&actions, ends[1], 0);
  // One word with "=", so that a negative exposure is not taken for an option.
  char exposure[48];
  std::snprintf(exposure, sizeof exposure, "--exposure=%.17g", display.exposure);
  std::vector<std::string> args = {viewer, "--preview", exposure, "--tonemap",
                                   tone_curve_name(display.curve)};
  if (display.srgb) args.emplace_back("--srgb");
  std::vector<char*> argv;
  for (std::string& arg : args) argv.push_back(arg.data());
  argv.push_back(nullptr);
  pid_t pid = -1;
  const int spawned = posix_spawn(&pid, viewer.c_str(), &actions, nullptr, argv.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  close(ends[1]);
  std::unique_ptr<PreviewWindow> window(new PreviewWindow(ends[0]));
  if (spawned != 0) {
    why = "cannot start " + viewer + ": " + std::strerror(spawned);
    return nullptr;
  }
  const PreviewHeader header{{kPreviewMagic[0], kPreviewMagic[1], kPreviewMagic[2],
                              kPreviewMagic[3], kPreviewMagic[4], kPreviewMagic[5],
                              kPreviewMagic[6], kPreviewMagic[7]},
                             width,
                             height};
  pollfd ready{ends[0], POLLIN, 0};
  char answer = 0;
  if (!window->send_all(&header, sizeof header) || poll(&ready, 1, kReadyTimeoutMs) != 1 ||
      read(ends[0], &answer, 1) != 1 || answer != kPreviewReady) {
    why = "clrt-view could not open a window";
    // It said why on standard error, and is gone or going: reaped so that it leaves no zombie.
    kill(pid, SIGTERM);
    waitpid(pid, nullptr, 0);
    return nullptr;
  }
  return window;
}

PreviewWindow::~PreviewWindow() { close(socket_); }

bool PreviewWindow::send_all(const void* data, std::size_t size) {
  const auto* bytes = static_cast<const char*>(data);
  while (size > 0) {
    const ssize_t sent = send(socket_, bytes, size, MSG_NOSIGNAL);
    if (sent < 0 && errno == EINTR) continue;
    if (sent <= 0) return false;
    bytes += sent;
    size -= static_cast<std::size_t>(sent);
  }
  return true;
}

void PreviewWindow::store(std::uint64_t first, std::uint32_t count, const dev::f4* pixels) {
  std::vector<float> rgb(3 * std::size_t{count});
  for (std::uint32_t p = 0; p < count; ++p) {
    rgb[3 * p] = pixels[p].x;
    rgb[3 * p + 1] = pixels[p].y;
    rgb[3 * p + 2] = pixels[p].z;
  }
  const PreviewBand band{first, count, 0};
  std::lock_guard<std::mutex> lock(mutex_);
  if (closed_) return;
  closed_ = !send_all(&band, sizeof band) || !send_all(rgb.data(), rgb.size() * sizeof(float));
}

}  // namespace clrt

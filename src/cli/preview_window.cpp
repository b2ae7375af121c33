#include "cli/preview_window.hpp"

#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <spawn.h>
#include <sys/socket.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <filesystem>

#include "image/preview_stream.hpp"

extern char** environ;

namespace clrt {
namespace {

// All `size` bytes to the socket: false once the other end is gone (or shut down).
bool send_all(int socket, const void* data, std::size_t size) {
  const auto* bytes = static_cast<const char*>(data);
  while (size > 0) {
    const ssize_t sent = send(socket, bytes, size, MSG_NOSIGNAL);
    if (sent < 0 && errno == EINTR) continue;
    if (sent <= 0) return false;
    bytes += sent;
    size -= static_cast<std::size_t>(sent);
  }
  return true;
}

// Ends a viewer that did not open its window: SIGTERM, and SIGKILL when it has not gone after the
// grace period (SDL turns SIGTERM into a quit event, which a viewer blocked on its display never
// reads); reaped either way, so that it leaves no zombie.
void end_viewer(pid_t pid) {
  kill(pid, SIGTERM);
  const auto deadline =
      std::chrono::steady_clock::now() + std::chrono::milliseconds(PreviewWindow::kEndGraceMs);
  while (std::chrono::steady_clock::now() < deadline) {
    const pid_t done = waitpid(pid, nullptr, WNOHANG);
    if (done == pid || (done < 0 && errno != EINTR)) return;
    usleep(10000);
  }
  kill(pid, SIGKILL);
  while (waitpid(pid, nullptr, 0) < 0 && errno == EINTR) {
  }
}

// Waits at most `timeout_ms` for the viewer's one-byte answer.
bool answered_ready(int socket, int timeout_ms) {
  pollfd ready{socket, POLLIN, 0};
  int polled = 0;
  do {
    polled = poll(&ready, 1, timeout_ms);
  } while (polled < 0 && errno == EINTR);
  char answer = 0;
  return polled == 1 && read(socket, &answer, 1) == 1 && answer == kPreviewReady;
}

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
  args.emplace_back(display.srgb ? "--srgb" : "--linear");
  std::vector<char*> argv;
  for (std::string& arg : args) argv.push_back(arg.data());
  argv.push_back(nullptr);
  pid_t pid = -1;
  const int spawned = posix_spawn(&pid, viewer.c_str(), &actions, nullptr, argv.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  close(ends[1]);
  if (spawned != 0) {
    close(ends[0]);
    why = "cannot start " + viewer + ": " + std::strerror(spawned);
    return nullptr;
  }
  const PreviewHeader header{{kPreviewMagic[0], kPreviewMagic[1], kPreviewMagic[2],
                              kPreviewMagic[3], kPreviewMagic[4], kPreviewMagic[5],
                              kPreviewMagic[6], kPreviewMagic[7]},
                             width,
                             height};
  // The header is 16 bytes: it fits the socket's buffer whether or not the viewer reads.
  if (!send_all(ends[0], &header, sizeof header) || !answered_ready(ends[0], kReadyTimeoutMs)) {
    why = "clrt-view could not open a window";
    // It said why on standard error, or it did not answer in time.
    close(ends[0]);
    end_viewer(pid);
    return nullptr;
  }
  return std::unique_ptr<PreviewWindow>(new PreviewWindow(ends[0]));
}

PreviewWindow::PreviewWindow(int socket) : socket_(socket) {
  sender_ = std::thread([this] { send_queued(); });
}

PreviewWindow::~PreviewWindow() {
  std::unique_lock<std::mutex> lock(mutex_);
  ending_ = true;
  changed_.notify_all();
  const bool drained = changed_.wait_for(lock, std::chrono::milliseconds(kEndGraceMs), [this] {
    return closed_ || (queue_.empty() && !sending_);
  });
  // A viewer that stopped reading holds the sender in send(): shutting the socket down ends it.
  if (!drained) shutdown(socket_, SHUT_RDWR);
  lock.unlock();
  sender_.join();
  close(socket_);
}

void PreviewWindow::send_queued() {
  std::unique_lock<std::mutex> lock(mutex_);
  for (;;) {
    changed_.wait(lock, [this] { return !queue_.empty() || ending_; });
    if (queue_.empty()) return;
    std::vector<char> message = std::move(queue_.front());
    queue_.pop_front();
    queued_bytes_ -= message.size();
    sending_ = true;
    lock.unlock();
    const bool sent = send_all(socket_, message.data(), message.size());
    lock.lock();
    sending_ = false;
    if (!sent) {
      closed_ = true;
      queue_.clear();
      queued_bytes_ = 0;
    }
    changed_.notify_all();
    if (closed_) return;
  }
}

void PreviewWindow::store(std::uint64_t first, std::uint32_t count, const dev::f4* pixels) {
  const PreviewBand band{first, count, 0};
  std::vector<char> message(sizeof band + 3 * sizeof(float) * std::size_t{count});
  std::memcpy(message.data(), &band, sizeof band);
  auto* rgb = reinterpret_cast<float*>(message.data() + sizeof band);
  for (std::uint32_t p = 0; p < count; ++p) {
    rgb[3 * p] = pixels[p].x;
    rgb[3 * p + 1] = pixels[p].y;
    rgb[3 * p + 2] = pixels[p].z;
  }
  std::lock_guard<std::mutex> lock(mutex_);
  if (closed_) return;
  if (queued_bytes_ + message.size() > kMaxQueuedBytes) {
    ++dropped_;
    return;
  }
  queued_bytes_ += message.size();
  queue_.push_back(std::move(message));
  changed_.notify_all();
}

std::uint64_t PreviewWindow::bands_dropped() {
  std::lock_guard<std::mutex> lock(mutex_);
  return dropped_;
}

}  // namespace clrt

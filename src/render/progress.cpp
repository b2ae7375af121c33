#include "render/progress.hpp"

#include <sys/ioctl.h>
#include <unistd.h>

#include <algorithm>
#include <cstdio>

namespace clrt {
namespace {

int terminal_columns() {
  winsize size{};
  if (ioctl(STDERR_FILENO, TIOCGWINSZ, &size) == 0 && size.ws_col > 0) return size.ws_col;
  return 80;
}

std::string duration_text(double seconds) {
  char text[32];
  if (seconds < 60) {
    std::snprintf(text, sizeof text, "%.1f s", seconds);
  } else {
    const long s = static_cast<long>(seconds);
    std::snprintf(text, sizeof text, "%ld:%02ld", s / 60, s % 60);
  }
  return text;
}

}  // namespace

Progress::Progress(bool enabled)
    : enabled_(enabled && isatty(STDERR_FILENO)),
      start_(std::chrono::steady_clock::now()),
      last_draw_(start_) {}

Progress::~Progress() { clear(); }

void Progress::phase(const std::string& name) {
  if (!enabled_) return;
  std::lock_guard<std::mutex> lock(mutex_);
  name_ = name;
  total_ = done_ = 0;
  draw(true);
}

void Progress::start(const std::string& name, std::uint64_t total) {
  if (!enabled_) return;
  std::lock_guard<std::mutex> lock(mutex_);
  name_ = name;
  total_ = total;
  done_ = 0;
  start_ = std::chrono::steady_clock::now();
  draw(true);
}

void Progress::advance(std::uint64_t done) {
  if (!enabled_) return;
  std::lock_guard<std::mutex> lock(mutex_);
  done_ += done;
  draw(done_ >= total_);
}

// Redrawing more than ten times a second only costs time.
void Progress::draw(bool force) {
  const auto now = std::chrono::steady_clock::now();
  if (!force && now - last_draw_ < std::chrono::milliseconds(100)) return;
  last_draw_ = now;
  const int columns = terminal_columns() - 1;  // the last column would wrap on some terminals
  std::string line = name_;
  if (total_ > 0) {
    const double fraction = std::min(1.0, static_cast<double>(done_) / static_cast<double>(total_));
    const double elapsed = std::chrono::duration<double>(now - start_).count();
    char tail[96];
    std::snprintf(tail, sizeof tail, " %3.0f%% %s", 100 * fraction, duration_text(elapsed).c_str());
    std::string text = tail;
    if (fraction > 0.02 && fraction < 1)
      text += ", " + duration_text(elapsed * (1 - fraction) / fraction) + " left";
    const int bar = columns - static_cast<int>(line.size() + text.size()) - 3;
    if (bar >= 10) {
      const int filled = static_cast<int>(fraction * bar);
      line += " [" + std::string(filled, '#') + std::string(bar - filled, '.') + "]";
    }
    line += text;
  }
  if (static_cast<int>(line.size()) > columns) line.resize(std::max(0, columns));
  std::fprintf(stderr, "\r\033[K%s", line.c_str());
  std::fflush(stderr);
  drawn_ = true;
}

void Progress::clear() {
  if (!drawn_) return;
  std::fprintf(stderr, "\r\033[K");
  std::fflush(stderr);
  drawn_ = false;
}

void Progress::message(const std::string& text) {
  std::lock_guard<std::mutex> lock(mutex_);
  const bool redraw = drawn_;
  clear();
  std::fprintf(stderr, "%s\n", text.c_str());
  if (redraw) draw(true);
}

void Progress::finish(const std::string& message) {
  if (!enabled_) return;
  std::lock_guard<std::mutex> lock(mutex_);
  clear();
  if (!message.empty()) std::fprintf(stderr, "%s\n", message.c_str());
}

}  // namespace clrt

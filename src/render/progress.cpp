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
    : Progress(Output{[](const std::string& text) {
                        std::fputs(text.c_str(), stderr);
                        std::fflush(stderr);
                      },
                      terminal_columns},
               std::chrono::steady_clock::now) {
  enabled_ = enabled && isatty(STDERR_FILENO);
  speaking_ = enabled;
}

Progress::Progress(Output output, Clock clock)
    : enabled_(true),
      output_(std::move(output)),
      clock_(std::move(clock)),
      start_(clock_()),
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
  note_.clear();
  total_ = total;
  done_ = first_done_ = 0;
  start_ = clock_();
  if (frames_ > 0) ++frame_;
  draw(true);
}

void Progress::frames(std::uint32_t count) {
  std::lock_guard<std::mutex> lock(mutex_);
  frames_ = count;
  frame_ = 0;
  all_first_done_ = 0;
}

void Progress::advance(std::uint64_t done) {
  if (!enabled_) return;
  std::lock_guard<std::mutex> lock(mutex_);
  done_ += done;
  if (first_done_ == 0) {
    first_done_ = done_;
    first_ = clock_();
  }
  if (frames_ > 0 && all_first_done_ == 0) {
    all_first_done_ = (frame_ - 1) * total_ + done_;
    all_first_ = first_;
  }
  draw(done_ >= total_);
}

void Progress::note(const std::string& text) {
  if (!enabled_) return;
  std::lock_guard<std::mutex> lock(mutex_);
  note_ = text;
  draw(true);
}

// Redrawing more than ten times a second only costs time.
void Progress::draw(bool force) {
  const auto now = clock_();
  if (!force && now - last_draw_ < std::chrono::milliseconds(100)) return;
  last_draw_ = now;
  const int columns = output_.columns() - 1;  // the last column would wrap on some terminals
  std::string line = name_;
  if (total_ > 0) {
    const double fraction = std::min(1.0, static_cast<double>(done_) / static_cast<double>(total_));
    const double elapsed = std::chrono::duration<double>(now - start_).count();
    char tail[96];
    std::snprintf(tail, sizeof tail, " %3.0f%%", 100 * fraction);
    std::string text = tail;
    if (!note_.empty()) text += " " + note_;
    text += " " + duration_text(elapsed);
    const double since_first = std::chrono::duration<double>(now - first_).count();
    if (done_ > first_done_ && done_ < total_ && since_first > 0) {
      const double rate = static_cast<double>(done_ - first_done_) / since_first;
      text += ", " + duration_text(static_cast<double>(total_ - done_) / rate) + " left";
    }
    text += time_left_of_all(now);
    const int bar = columns - static_cast<int>(line.size() + text.size()) - 3;
    if (bar >= 10) {
      const int filled = static_cast<int>(fraction * bar);
      line += " [" + std::string(filled, '#') + std::string(bar - filled, '.') + "]";
    }
    line += text;
  }
  if (static_cast<int>(line.size()) > columns) line.resize(std::max(0, columns));
  output_.write("\r\033[K" + line);
  drawn_ = true;
}

// Over the frames, from the rate since the first piece of the first frame drawn: each frame has
// the same pixels.
std::string Progress::time_left_of_all(std::chrono::steady_clock::time_point now) const {
  if (frames_ < 2 || frame_ == 0 || all_first_done_ == 0) return "";
  const std::uint64_t all = static_cast<std::uint64_t>(frames_) * total_;
  const std::uint64_t done = (frame_ - 1) * total_ + done_;
  const double since_first = std::chrono::duration<double>(now - all_first_).count();
  if (done <= all_first_done_ || done >= all || since_first <= 0) return "";
  const double rate = static_cast<double>(done - all_first_done_) / since_first;
  return ", all frames " + duration_text(static_cast<double>(all - done) / rate) + " left";
}

void Progress::clear() {
  if (!drawn_) return;
  output_.write("\r\033[K");
  drawn_ = false;
}

void Progress::message(const std::string& text) {
  std::lock_guard<std::mutex> lock(mutex_);
  const bool redraw = drawn_;
  clear();
  output_.write(text + "\n");
  if (redraw) draw(true);
}

void Progress::log(const std::string& text) {
  if (enabled_ || !speaking_) return;
  output_.write(text + "\n");
}

void Progress::finish(const std::string& message) {
  if (!enabled_) {
    if (speaking_ && !message.empty()) output_.write(message + "\n");
    return;
  }
  std::lock_guard<std::mutex> lock(mutex_);
  clear();
  if (!message.empty()) output_.write(message + "\n");
}

}  // namespace clrt

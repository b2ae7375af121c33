// The progress line on stderr, drawn only when stderr is a terminal (and not --quiet): the
// phase (load, BVH, kernel build, render, write), and while a long phase runs a bar that fits
// the terminal's width with the share done, the time so far and an estimate of the time left.
// It ends with what was written. Redirected output never sees any of it.
#pragma once

#include <chrono>
#include <cstdint>
#include <mutex>
#include <string>

namespace clrt {

class Progress {
 public:
  // Draws nothing unless `enabled` and stderr is a terminal.
  explicit Progress(bool enabled);
  ~Progress();
  Progress(const Progress&) = delete;
  Progress& operator=(const Progress&) = delete;

  bool drawing() const { return enabled_; }

  // A phase without a bar ("loading scene.ray").
  void phase(const std::string& name);
  // A phase with a bar over `total` units ("rendering", "frame 3/24").
  void start(const std::string& name, std::uint64_t total);
  void advance(std::uint64_t done);  // thread-safe
  // Prints `text` on a line of its own above the progress line (or just prints it when no line
  // is drawn: stderr is not a terminal, or --quiet).
  void message(const std::string& text);
  // Clears the line, then prints `message` on a line of its own when there is one.
  void finish(const std::string& message = "");

 private:
  void draw(bool force);
  void clear();

  bool enabled_;
  std::string name_;
  std::uint64_t total_ = 0, done_ = 0;
  bool drawn_ = false;
  std::chrono::steady_clock::time_point start_, last_draw_;
  std::mutex mutex_;
};

}  // namespace clrt

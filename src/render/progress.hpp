// The progress line on stderr, drawn only when stderr is a terminal (and not --quiet): the
// phase (load, kernel build, BVH, render, write), and while a long phase runs a bar that fits
// the terminal's width with the share done, the time so far and an estimate of the time left;
// over the frames of an animation, also the time left for all of them. It ends with what was
// written. Redirected output sees none of the line, only a line per image written (a log).
//
// The time left comes from the rate since the first piece of work was done, never from the
// start: the first waves also pay for work done once (PoCL compiles a kernel for its work-group
// size at its first launch), and counting that as the rendering rate once made a 0.3 s render
// say "19.8 s left". Until a second piece arrives there is no estimate rather than a wrong one.
#pragma once

#include <chrono>
#include <cstdint>
#include <functional>
#include <mutex>
#include <string>

namespace clrt {

class Progress {
 public:
  using Clock = std::function<std::chrono::steady_clock::time_point()>;
  // Where a drawn line goes and how wide it may be (a test's own, or the terminal).
  struct Output {
    std::function<void(const std::string& text)> write;
    std::function<int()> columns;
  };

  // Draws nothing unless `enabled` and stderr is a terminal; prints nothing unless `enabled`.
  explicit Progress(bool enabled);
  // Always draws, into `output`, reading the time from `clock`.
  Progress(Output output, Clock clock);
  ~Progress();
  Progress(const Progress&) = delete;
  Progress& operator=(const Progress&) = delete;

  bool drawing() const { return enabled_; }

  // A phase without a bar ("loading scene.ray").
  void phase(const std::string& name);
  // A phase with a bar over `total` units ("rendering", "frame 3/24").
  void start(const std::string& name, std::uint64_t total);
  void advance(std::uint64_t done);  // thread-safe
  // A few words shown after the share done until the next start ("24/64 spp").
  void note(const std::string& text);
  // The bars that follow are the `count` frames of one animation, of equal size: the line adds
  // the time left for all of them.
  void frames(std::uint32_t count);
  // Prints `text` on a line of its own above the progress line (or just prints it when no line
  // is drawn: stderr is not a terminal, or --quiet).
  void message(const std::string& text);
  // Prints `text` on a line of its own only when no line is drawn, for what the line shows on a
  // terminal but a log should keep (each frame written).
  void log(const std::string& text);
  // Clears the line, then prints `message` on a line of its own when there is one (also when no
  // line is drawn, unless --quiet).
  void finish(const std::string& message = "");

 private:
  void draw(bool force);
  std::string time_left_of_all(std::chrono::steady_clock::time_point now) const;
  void clear();

  bool enabled_;
  bool speaking_ = true;  // not --quiet
  Output output_;
  Clock clock_;
  std::string name_, note_;
  std::uint64_t total_ = 0, done_ = 0;
  std::uint64_t first_done_ = 0;  // done when the first piece arrived; 0 before
  bool drawn_ = false;
  std::chrono::steady_clock::time_point start_, first_, last_draw_;
  // The animation's frames: how many, which one the bar shows (1-based), and the units done of
  // all of them when the first piece arrived, and when.
  std::uint32_t frames_ = 0, frame_ = 0;
  std::uint64_t all_first_done_ = 0;
  std::chrono::steady_clock::time_point all_first_;
  std::mutex mutex_;
};

}  // namespace clrt

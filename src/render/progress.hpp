// A progress bar on stderr for long renders; silent unless stderr is a terminal.
#pragma once

#include <chrono>
#include <cstdint>
#include <mutex>

namespace clrt {

class Progress {
 public:
  // `enabled` false (--quiet) or stderr not a terminal: nothing is ever printed.
  Progress(std::uint64_t total, bool enabled);
  ~Progress();
  Progress(const Progress&) = delete;
  Progress& operator=(const Progress&) = delete;

  void advance(std::uint64_t done);  // thread-safe
  void finish();                     // clears the line

 private:
  void draw();

  std::uint64_t total_, done_ = 0;
  bool enabled_;
  bool drawn_ = false;
  std::chrono::steady_clock::time_point start_, last_draw_;
  std::mutex mutex_;
};

}  // namespace clrt

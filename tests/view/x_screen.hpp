// A display of its own for a test (Xvfb, on a free display number), the programs the
// test starts on it, and the pixels of a top-level window as the X server holds them: read by
// XGetImage, independent of the program that drew them.
#pragma once

#include <sys/types.h>

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace clrt::test {

struct WindowPixels {
  int width = 0, height = 0;
  std::vector<std::uint32_t> pixels;  // 0x00RRGGBB, row 0 at the top
  std::string title;
};

class XScreen {
 public:
  // Whether Xvfb is installed; without it the tests report skipped.
  static bool available();
  static constexpr int kWidth = 1600, kHeight = 1200;  // the screen's pixels
  // Starts Xvfb on a free display and waits until it takes connections; std::runtime_error if
  // it does not come up.
  XScreen();
  ~XScreen();  // ends Xvfb and every program started on it
  XScreen(const XScreen&) = delete;
  XScreen& operator=(const XScreen&) = delete;

  const std::string& display() const { return display_; }
  // Runs `argv` with DISPLAY set to this screen (and SDL on its X11 driver); its output goes
  // to `log`.
  pid_t start(const std::vector<std::string>& argv, const std::string& log);
  // Waits for a program start() started to exit; its exit status (-1 if a signal ended it).
  int wait(pid_t pid);
  // Gives the window whose title starts with `prefix` the keyboard focus and sends it a press
  // and release of the key `keysym` (XK_g, XK_Tab...); false when no such window is mapped.
  bool press(const std::string& prefix, unsigned long keysym) const;
  // The first top-level window whose title starts with `prefix`, if one is mapped.
  std::optional<WindowPixels> grab(const std::string& prefix) const;

 private:
  pid_t server_ = -1;
  std::string display_;
  std::vector<pid_t> programs_;
};

}  // namespace clrt::test

#include "x_screen.hpp"

#include <X11/Xlib.h>
#include <X11/Xutil.h>
#include <fcntl.h>
#include <signal.h>
#include <sys/prctl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cstdlib>
#include <stdexcept>

namespace clrt::test {
namespace {

// In the child: a test that dies leaves no server or viewer behind.
[[noreturn]] void exec_or_exit(const std::vector<std::string>& argv) {
  prctl(PR_SET_PDEATHSIG, SIGTERM);
  std::vector<char*> args;
  for (const std::string& arg : argv) args.push_back(const_cast<char*>(arg.c_str()));
  args.push_back(nullptr);
  execvp(args[0], args.data());
  _exit(127);
}

void end(pid_t pid) {
  kill(pid, SIGTERM);
  waitpid(pid, nullptr, 0);
}

std::string window_title(Display* display, Window window) {
  XTextProperty name{};
  if (!XGetWMName(display, window, &name) || !name.value) return "";
  std::string title(reinterpret_cast<const char*>(name.value), name.nitems);
  XFree(name.value);
  return title;
}

bool can_connect(const std::string& display) {
  Display* connection = XOpenDisplay(display.c_str());
  if (connection) XCloseDisplay(connection);
  return connection != nullptr;
}

// A window that changes size while it is read fails with BadMatch: the grab is tried again
// rather than ending the test as Xlib's default handler would.
int ignore_error(Display*, XErrorEvent*) { return 0; }

}  // namespace

bool XScreen::available() { return std::system("command -v Xvfb >/dev/null 2>&1") == 0; }

XScreen::XScreen() {
  // A display number from the process id, so that tests running at once rarely try the same
  // one; an Xvfb that finds its number taken exits, and the next number is tried.
  for (int attempt = 0; attempt < 20; ++attempt) {
    display_ = ":" + std::to_string(100 + (getpid() + attempt * 37) % 5000);
    if (can_connect(display_)) continue;
    server_ = fork();
    if (server_ == 0) {
      const int devnull = open("/dev/null", O_WRONLY);
      dup2(devnull, 1);
      dup2(devnull, 2);
      // -noreset: the server would otherwise reset, refusing connections for a moment, each time
      // its last client (this test's check that it is up) leaves.
      const std::string size = std::to_string(kWidth) + "x" + std::to_string(kHeight) + "x24";
      exec_or_exit({"Xvfb", display_, "-screen", "0", size, "-nolisten", "tcp", "-noreset"});
    }
    for (int wait = 0; wait < 200; ++wait) {
      if (can_connect(display_)) return;
      if (waitpid(server_, nullptr, WNOHANG) == server_) break;
      usleep(25000);
    }
    end(server_);
  }
  throw std::runtime_error("Xvfb did not start");
}

XScreen::~XScreen() {
  for (pid_t pid : programs_) end(pid);
  end(server_);
}

pid_t XScreen::start(const std::vector<std::string>& argv, const std::string& log) {
  const pid_t pid = fork();
  if (pid == 0) {
    setenv("DISPLAY", display_.c_str(), 1);
    setenv("SDL_VIDEODRIVER", "x11", 1);
    const int out = open(log.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    dup2(out, 1);
    dup2(out, 2);
    exec_or_exit(argv);
  }
  programs_.push_back(pid);
  return pid;
}

int XScreen::wait(pid_t pid) {
  int status = 0;
  waitpid(pid, &status, 0);
  programs_.erase(std::remove(programs_.begin(), programs_.end(), pid), programs_.end());
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

namespace {

// The first mapped top-level window whose title starts with `prefix`, and its size and title.
std::optional<std::pair<Window, WindowPixels>> find_window(Display* display,
                                                           const std::string& prefix) {
  std::optional<std::pair<Window, WindowPixels>> found;
  Window root = 0, parent = 0, *children = nullptr;
  unsigned count = 0;
  XQueryTree(display, DefaultRootWindow(display), &root, &parent, &children, &count);
  for (unsigned i = 0; i < count && !found; ++i) {
    XWindowAttributes attributes{};
    const std::string title = window_title(display, children[i]);
    if (title.rfind(prefix, 0) == 0 && XGetWindowAttributes(display, children[i], &attributes) &&
        attributes.map_state == IsViewable)
      found.emplace(children[i], WindowPixels{attributes.width, attributes.height, {}, title});
  }
  if (children) XFree(children);
  return found;
}

}  // namespace

bool XScreen::press(const std::string& prefix, unsigned long keysym) const {
  XSetErrorHandler(ignore_error);
  Display* display = XOpenDisplay(display_.c_str());
  if (!display) return false;
  const auto window = find_window(display, prefix);
  if (window) {
    XSetInputFocus(display, window->first, RevertToParent, CurrentTime);
    XKeyEvent key{};
    key.display = display;
    key.window = window->first;
    key.root = DefaultRootWindow(display);
    key.same_screen = True;
    key.keycode = XKeysymToKeycode(display, keysym);
    for (int type : {KeyPress, KeyRelease}) {
      key.type = type;
      XSendEvent(display, window->first, True,
                 type == KeyPress ? KeyPressMask : KeyReleaseMask, reinterpret_cast<XEvent*>(&key));
    }
    XSync(display, False);
  }
  XCloseDisplay(display);
  return window.has_value();
}

std::optional<WindowPixels> XScreen::grab(const std::string& prefix) const {
  XSetErrorHandler(ignore_error);
  Display* display = XOpenDisplay(display_.c_str());
  if (!display) return std::nullopt;
  std::optional<WindowPixels> found;
  if (auto window = find_window(display, prefix)) {
    WindowPixels& pixels = window->second;
    XImage* image = XGetImage(display, window->first, 0, 0, static_cast<unsigned>(pixels.width),
                              static_cast<unsigned>(pixels.height), AllPlanes, ZPixmap);
    if (image) {
      for (int y = 0; y < pixels.height; ++y)
        for (int x = 0; x < pixels.width; ++x)
          pixels.pixels.push_back(static_cast<std::uint32_t>(XGetPixel(image, x, y)) & 0xffffff);
      XDestroyImage(image);
      found = std::move(pixels);
    }
  }
  XCloseDisplay(display);
  return found;
}

}  // namespace clrt::test

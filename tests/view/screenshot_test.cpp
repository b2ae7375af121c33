// clrt-view under Xvfb: the window's pixels, read back from the X server, against the picture
// the viewer's own functions compose on the host, and against values worked out by hand.
#include <arpa/inet.h>
#include <netinet/in.h>
#include <sys/socket.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <catch2/catch.hpp>
#include <chrono>
#include <cstdlib>
#include <cmath>
#include <fstream>
#include <iterator>
#include <thread>

#include "image/image.hpp"
#include "png_chunks.hpp"
#include "scratch_dir.hpp"
#include "skip_test.hpp"
#include "controls.hpp"
#include "x_screen.hpp"

#include <X11/Xlib.h>
#include <X11/keysym.h>

using namespace clrt;
using namespace clrt::view;
using clrt::test::png_declaring;
using clrt::test::write_bytes;
using clrt::test::ScratchDir;
using clrt::test::WindowPixels;
using clrt::test::XScreen;

namespace {

// What the viewer may fill of the Xvfb screen (window.cpp).
constexpr ScreenArea kXvfbArea{XScreen::kWidth - kWindowFrame.width,
                               XScreen::kHeight - kWindowFrame.height};

std::string text_of(const std::string& path) {
  std::ifstream in(path);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

// How many pixels of the window differ from `expected` (all of them when the sizes differ).
std::size_t differing(const WindowPixels& window, const Canvas& expected) {
  if (window.width != expected.width || window.height != expected.height)
    return expected.pixels.size();
  std::size_t count = 0;
  for (std::size_t i = 0; i < expected.pixels.size(); ++i)
    count += window.pixels[i] != expected.pixels[i];
  return count;
}

// Grabs the viewer's window until it shows `expected` with `title_part` in its title (it may
// take a moment to map and draw), for at most ten seconds; the last grab when it never does.
WindowPixels shown(const XScreen& screen, const Canvas& expected,
                   const std::string& title_part = "") {
  WindowPixels last;
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(10);
  while (std::chrono::steady_clock::now() < deadline) {
    if (auto window = screen.grab("clrt-view")) {
      last = std::move(*window);
      if (differing(last, expected) == 0 && last.title.find(title_part) != std::string::npos)
        break;
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
  }
  return last;
}

// 8-bit RGBA pixels as the window should hold them, each a zoom x zoom square: worked out here
// rather than by the viewer's compose(), to check its identity at exposure 0 and gamma 1.
Canvas magnified(const std::vector<std::uint8_t>& rgba, int width, int height, int zoom) {
  Canvas canvas{width * zoom, height * zoom, {}};
  for (int y = 0; y < canvas.height; ++y)
    for (int x = 0; x < canvas.width; ++x) {
      const std::uint8_t* p = &rgba[4 * (std::size_t(y / zoom) * width + x / zoom)];
      canvas.pixels.push_back(std::uint32_t{p[0]} << 16 | std::uint32_t{p[1]} << 8 | p[2]);
    }
  return canvas;
}

// A 16x12 HDR image: a ramp in red past 1, green in steps, blue fixed at 0.25.
FloatImage hdr_ramp() {
  std::vector<float> rgb;
  for (int y = 0; y < 12; ++y)
    for (int x = 0; x < 16; ++x)
      rgb.insert(rgb.end(), {static_cast<float>(x) / 8, static_cast<float>(y) / 11, 0.25f});
  return FloatImage(16, 12, std::move(rgb));
}

void check_shows(const WindowPixels& window, const Canvas& expected, const std::string& log) {
  INFO("clrt-view's output: " << text_of(log));
  INFO("window " << window.width << "x" << window.height << " '" << window.title << "', expected "
                 << expected.width << "x" << expected.height);
  CHECK(differing(window, expected) == 0);
}

}  // namespace

TEST_CASE("clrt-view shows a PFM with exposure and gamma as the host tone-maps it",
          "[view][screenshot]") {
  if (!XScreen::available()) CLRT_SKIP_TEST("Xvfb is not installed");
  ScratchDir dir;
  const std::string pfm = dir.file("ramp.pfm");
  write_image(pfm, hdr_ramp());
  XScreen screen;
  const std::string log = dir.file("view.log");
  screen.start({CLRT_VIEW, pfm, "--exposure", "1", "--gamma", "2.2"}, log);

  ViewState state;
  state.tone = {1, 2.2};
  state.zoom = fitting_zoom(16, 12, 1, kXvfbArea);
  const ViewSources sources = make_sources(hdr_ramp(), nullptr);
  const Canvas expected = compose(layout_view(state, sources), state, sources);
  const WindowPixels window = shown(screen, expected);
  check_shows(window, expected, log);
  REQUIRE(window.width == 16 * 64);
  // By hand: blue 0.25 at +1 stop is 0.5, shown as 0.5^(1/2.2) = 0.7297, byte 186; red of
  // column 8 (1.0) doubles past 1 and clamps to 255; green of row 0 is 0.
  CHECK(window.pixels[8 * 64] == 0xff00baU);
  CHECK(window.title.find("exposure +1.0 gamma 2.2") != std::string::npos);
}

TEST_CASE("clrt-view reduces an image wider than the screen until it fits, and --zoom takes any "
          "factor",
          "[view][screenshot]") {
  if (!XScreen::available()) CLRT_SKIP_TEST("Xvfb is not installed");
  ScratchDir dir;
  const int width = 2 * XScreen::kWidth, height = 60;
  std::vector<float> rgb;
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x)
      rgb.insert(rgb.end(), {float(x % 7) / 6, float(y) / height, float(x) / width});
  const FloatImage wide(width, height, std::move(rgb));
  const std::string pfm = dir.file("wide.pfm");
  write_image(pfm, wide);
  const ViewSources sources = make_sources(wide, nullptr);
  for (const std::vector<std::string>& zoom :
       {std::vector<std::string>{}, std::vector<std::string>{"--zoom", "0.3"}}) {
    INFO((zoom.empty() ? "fitted" : "--zoom 0.3"));
    XScreen screen;
    const std::string log = dir.file("view.log");
    std::vector<std::string> command{CLRT_VIEW, pfm};
    command.insert(command.end(), zoom.begin(), zoom.end());
    screen.start(command, log);
    ViewState state;
    state.tone.srgb = true;  // a PFM holds linear values: shown through sRGB unless --linear
    state.zoom = zoom.empty() ? fitting_zoom(width, height, 1, kXvfbArea) : 0.3;
    const Canvas expected = compose(layout_view(state, sources), state, sources);
    const WindowPixels window = shown(screen, expected);
    check_shows(window, expected, log);
    CHECK(window.width <= kXvfbArea.width);
  }
}

TEST_CASE("clrt-view shows the frame of an FSF animation it is asked for, paused",
          "[view][screenshot]") {
  if (!XScreen::available()) CLRT_SKIP_TEST("Xvfb is not installed");
  ScratchDir dir;
  const std::string fsf = dir.file("turn.fsf");
  std::vector<std::vector<std::uint8_t>> frames;
  for (std::uint8_t f = 0; f < 3; ++f) {
    std::vector<std::uint8_t> rgba;
    for (int i = 0; i < 16 * 12; ++i)
      rgba.insert(rgba.end(), {static_cast<std::uint8_t>(80 * f), static_cast<std::uint8_t>(i),
                               static_cast<std::uint8_t>(255 - i), 255});
    frames.push_back(std::move(rgba));
  }
  write_image(fsf, Rgba8Image(16, 12, frames));
  XScreen screen;
  const std::string log = dir.file("view.log");
  screen.start({CLRT_VIEW, fsf, "--frame", "2", "--pause", "--zoom", "4"}, log);

  // 8-bit pixels are shown as they are: frame 2's bytes, each a 4x4 square.
  const Canvas expected = magnified(frames[1], 16, 12, 4);
  const WindowPixels window = shown(screen, expected);
  check_shows(window, expected, log);
  CHECK(window.title.find("frame 2/3 paused") != std::string::npos);
}

TEST_CASE("clrt-view compares two images side by side with their difference",
          "[view][screenshot]") {
  if (!XScreen::available()) CLRT_SKIP_TEST("Xvfb is not installed");
  ScratchDir dir;
  const std::string a = dir.file("a.pfm"), b = dir.file("b.pfm");
  FloatImage other = hdr_ramp();
  for (std::size_t i = 0; i < other.rgb.size(); i += 7) other.rgb[i] += 0.125f;
  write_image(a, hdr_ramp());
  write_image(b, other);
  XScreen screen;
  const std::string log = dir.file("view.log");
  screen.start({CLRT_VIEW, a, b, "--side-by-side", "--difference", "--linear", "--zoom", "3"}, log);

  ViewState state;
  state.side_by_side = state.show_difference = true;
  state.zoom = 3;
  const AnyImage any_b = other;
  const ViewSources sources = make_sources(hdr_ramp(), &any_b);
  const Canvas expected = compose(layout_view(state, sources), state, sources);
  const WindowPixels window = shown(screen, expected);
  check_shows(window, expected, log);
  CHECK(window.width == 3 * 16 * 3 + 2 * kGap);
  // The gap between two pictures, and a pixel that differs: white in the difference (its
  // largest), a pixel that does not: black.
  CHECK(window.pixels[48] == kBackground);
  const int difference_x = 2 * (48 + kGap);
  CHECK(window.pixels[difference_x] == 0xff0000U);  // red of pixel 0 moved by 0.125
  CHECK(window.pixels[difference_x + 3] == 0x000000U);
}

TEST_CASE("clrt-view's keys, sent through the X server, flip, show the difference and change "
          "the tone",
          "[view][screenshot][keys]") {
  if (!XScreen::available()) CLRT_SKIP_TEST("Xvfb is not installed");
  ScratchDir dir;
  const std::string a = dir.file("a.pfm"), b = dir.file("b.pfm");
  FloatImage other = hdr_ramp();
  for (float& value : other.rgb) value *= 0.5f;
  write_image(a, hdr_ramp());
  write_image(b, other);
  XScreen screen;
  const std::string log = dir.file("view.log");
  screen.start({CLRT_VIEW, a, b, "--linear", "--zoom", "2"}, log);
  const AnyImage any_b = other;
  const ViewSources sources = make_sources(hdr_ramp(), &any_b);
  ViewState state;
  state.zoom = 2;
  const auto check_state = [&] {
    const Canvas expected = compose(layout_view(state, sources), state, sources);
    check_shows(shown(screen, expected), expected, log);
  };
  check_state();
  // Each key, then the picture it should lead to.
  const std::pair<unsigned long, void (*)(ViewState&)> steps[] = {
      {XK_Tab, [](ViewState& s) { s.flipped = Picture::B; }},
      {XK_g, [](ViewState& s) { s.tone.gamma = kDisplayGamma; }},
      {XK_equal, [](ViewState& s) { s.tone.exposure = kExposureStep; }},
      {XK_e, [](ViewState& s) { s.tone.srgb = true; }},
      {XK_f, [](ViewState& s) { s.tone.curve = ToneCurve::Filmic; }},
      {XK_d, [](ViewState& s) { s.show_difference = true; }},
      {XK_s, [](ViewState& s) { s.side_by_side = true; }},
  };
  for (const auto& [key, change] : steps) {
    INFO("after key " << XKeysymToString(key));
    REQUIRE(screen.press("clrt-view", key));
    change(state);
    check_state();
  }
}

TEST_CASE("clrt --preview shows the render in clrt-view as it fills in, and the same image is "
          "written",
          "[view][screenshot][preview]") {
  if (!XScreen::available()) CLRT_SKIP_TEST("Xvfb is not installed");
  // The window shows what the file holds, also through path mode's sRGB and the tone options.
  const std::vector<std::string> picture =
      GENERATE(std::vector<std::string>{},
               std::vector<std::string>{"--mode", "path", "--exposure=-0.5", "--tonemap", "filmic"});
  ScratchDir dir;
  const std::string png = dir.file("reflect.png"), plain = dir.file("plain.png");
  const std::string scene = std::string(CLRT_SOURCE_DIR) + "/scenes/reflect.ray";
  std::vector<std::string> command{CLRT_EXE, scene, "--resolution", "24x18", "-q"};
  command.insert(command.end(), picture.begin(), picture.end());
  XScreen screen;
  const std::string log = dir.file("clrt.log");
  std::vector<std::string> previewed = command;
  previewed.insert(previewed.end(), {"--preview", "-o", png});
  const pid_t clrt = screen.start(previewed, log);
  REQUIRE(screen.wait(clrt) == 0);
  CHECK(text_of(log).find("warning") == std::string::npos);
  command.insert(command.end(), {"-o", plain});
  const pid_t without = screen.start(command, dir.file("plain.log"));
  REQUIRE(screen.wait(without) == 0);
  const std::vector<std::uint8_t> bytes = read_png(png).frames[0];
  CHECK(bytes == read_png(plain).frames[0]);

  // The window holds the finished render: the PNG's bytes, magnified.
  const Canvas expected = magnified(bytes, 24, 18, static_cast<int>(fitting_zoom(24, 18, 1, kXvfbArea)));
  const WindowPixels window = shown(screen, expected, "render complete");
  check_shows(window, expected, log);
  CHECK(window.title.find("render complete") != std::string::npos);
}

TEST_CASE("clrt --preview with a display that takes the connection and never answers renders "
          "anyway",
          "[view][preview]") {
  // A listening socket on X's port for display N: the kernel accepts the connection, and no X
  // server ever replies, as over a stalled X forwarding.
  const int listener = socket(AF_INET, SOCK_STREAM | SOCK_CLOEXEC, 0);
  REQUIRE(listener >= 0);
  int display = 0;
  for (int n = 50; n < 100 && !display; ++n) {
    sockaddr_in address{};
    address.sin_family = AF_INET;
    address.sin_port = htons(static_cast<std::uint16_t>(6000 + n));
    address.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
    if (bind(listener, reinterpret_cast<sockaddr*>(&address), sizeof address) == 0) display = n;
  }
  REQUIRE(display);
  REQUIRE(listen(listener, 8) == 0);
  ScratchDir dir;
  const std::string png = dir.file("out.png");
  const std::string scene = std::string(CLRT_SOURCE_DIR) + "/scenes/reflect.ray";
  const std::string command = "env -u WAYLAND_DISPLAY DISPLAY=127.0.0.1:" +
                              std::to_string(display) + " SDL_VIDEODRIVER=x11 timeout 180 '" +
                              std::string(CLRT_EXE) + "' '" + scene +
                              "' --resolution 8x6 --preview -o '" + png + "' 2>'" +
                              dir.file("err.txt") + "'";
  const int status = std::system(command.c_str());
  close(listener);
  const std::string err = text_of(dir.file("err.txt"));
  INFO(err);
  REQUIRE(WIFEXITED(status));
  CHECK(WEXITSTATUS(status) == 0);  // 124 had it hung
  CHECK(err.find("clrt: warning: --preview: clrt-view could not open a window; rendering "
                 "without it") != std::string::npos);
  CHECK(read_png(png).width == 8);
}

TEST_CASE("clrt --preview without a display says so and renders anyway",
          "[view][preview]") {
  ScratchDir dir;
  const std::string png = dir.file("out.png");
  const std::string scene = std::string(CLRT_SOURCE_DIR) + "/scenes/reflect.ray";
  const std::string command = "env -u DISPLAY -u WAYLAND_DISPLAY SDL_VIDEODRIVER=x11 '" +
                              std::string(CLRT_EXE) + "' '" + scene +
                              "' --resolution 8x6 --preview -q -o '" + png + "' 2>'" +
                              dir.file("err.txt") + "'";
  CHECK(std::system(command.c_str()) == 0);
  CHECK(read_png(png).width == 8);
  CHECK(text_of(dir.file("err.txt")).find("clrt: warning: --preview: clrt-view could not open a "
                                          "window; rendering without it") != std::string::npos);
}

TEST_CASE("clrt-view refuses, from the header and before any window, an image the memory cannot "
          "hold",
          "[view][memory]") {
#if defined(__SANITIZE_ADDRESS__)
  CLRT_SKIP_TEST("AddressSanitizer cannot run under ulimit -v");
#endif
  ScratchDir dir;
  // A PNG of a few hundred bytes declaring 16384 x 16384 pixels: 4 GiB as 8-bit RGBA and floats.
  const std::string big = dir.file("big.png");
  write_bytes(big, png_declaring(16384, 16384));
  const std::string command = "env -u DISPLAY sh -c \"ulimit -v 262144 && exec '" +
                              std::string(CLRT_VIEW) + "' '" + big + "'\" 2>'" +
                              dir.file("err.txt") + "'";
  const int raw = std::system(command.c_str());
  REQUIRE(WIFEXITED(raw));
  const std::string err = text_of(dir.file("err.txt"));
  INFO(err);
  CHECK(WEXITSTATUS(raw) == 1);
  CHECK(err.rfind("clrt-view: error: showing " + big + " needs ", 0) == 0);
  CHECK(err.find(" MiB available (RLIMIT_AS, ulimit -v)") != std::string::npos);
}

TEST_CASE("clrt-view's usage errors exit 2 and an unreadable image 1, before any window",
          "[view][usage]") {
  ScratchDir dir;
  const auto status = [&](const std::string& args) {
    const std::string command = "env -u DISPLAY '" + std::string(CLRT_VIEW) + "' " + args +
                                " 2>'" + dir.file("err.txt") + "'";
    const int raw = std::system(command.c_str());
    return WIFEXITED(raw) ? WEXITSTATUS(raw) : -1;
  };
  CHECK(status("") == 2);
  CHECK(text_of(dir.file("err.txt")) == "clrt-view: error: name an image to show\n");
  CHECK(status("--preview a.png") == 2);
  CHECK(status("--gamma 0 a.png") == 2);
  CHECK(status("--zoom 0 a.png") == 2);
  CHECK(text_of(dir.file("err.txt")).rfind("clrt-view: error: --zoom: 0 is not in the range ", 0) == 0);
  CHECK(status("'" + dir.file("missing.pfm") + "'") == 1);
  CHECK(text_of(dir.file("err.txt")).rfind("clrt-view: error: ", 0) == 0);
  write_image(dir.file("a.pfm"), hdr_ramp());
  write_image(dir.file("b.pfm"), FloatImage(1, 1, {0, 0, 0}));
  CHECK(status("'" + dir.file("a.pfm") + "' '" + dir.file("b.pfm") + "'") == 1);
  CHECK(text_of(dir.file("err.txt")) ==
        "clrt-view: error: the images differ in size: 16x12 against 1x1\n");
  // A FIFO is refused before it is opened for reading, which would wait for a writer: timeout's
  // 124 fails the check where the refusal is missing.
  const std::string fifo = dir.file("fifo.pfm");
  REQUIRE(::mkfifo(fifo.c_str(), 0600) == 0);
  const int raw = std::system(("env -u DISPLAY timeout 20 '" + std::string(CLRT_VIEW) + "' '" +
                               fifo + "' 2>'" + dir.file("err.txt") + "'")
                                  .c_str());
  CHECK((WIFEXITED(raw) && WEXITSTATUS(raw) == 2));
  CHECK(text_of(dir.file("err.txt")) ==
        "clrt-view: error: cannot read " + fifo + ": it is not a regular file\n");
}

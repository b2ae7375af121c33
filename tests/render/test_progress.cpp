// The progress line driven by a fake clock: its time left is honest from the first second (the
// rate since the first piece of work, not since the start, which includes one-off costs), it
// shows no estimate before it can make one, and it fits the width it is given.
#include <catch2/catch.hpp>

#include <chrono>
#include <string>

#include "render/progress.hpp"

using namespace clrt;

namespace {

struct FakeTerminal {
  std::string text;  // everything written
  std::chrono::steady_clock::time_point now{};
  int columns = 80;

  Progress progress() {
    return Progress({[this](const std::string& t) { text += t; }, [this] { return columns; }},
                    [this] { return now; });
  }
  // The line as it stands: what follows the last carriage return and clear.
  std::string line() const {
    const std::size_t at = text.rfind("\r\033[K");
    return at == std::string::npos ? text : text.substr(at + 4);
  }
  void wait(double seconds) {
    now += std::chrono::duration_cast<std::chrono::steady_clock::duration>(
        std::chrono::duration<double>(seconds));
  }
};

}  // namespace

TEST_CASE("the time left counts from the first piece of work, not from the start", "[progress]") {
  FakeTerminal terminal;
  Progress progress = terminal.progress();
  progress.start("rendering", 100);
  CHECK(terminal.line().find("left") == std::string::npos);
  terminal.wait(5.0);  // the first wave also compiled the kernels for their work-group size
  progress.advance(10);
  CHECK(terminal.line().find("left") == std::string::npos);  // no rate known yet: no estimate
  terminal.wait(0.1);
  progress.advance(10);
  // 10 pieces in 0.1 s, 80 to go: 0.8 s (counting from the start would say 20.4 s).
  CHECK(terminal.line().find(" 20% ") != std::string::npos);
  CHECK(terminal.line().find("0.8 s left") != std::string::npos);
  terminal.wait(0.4);
  progress.advance(40);
  CHECK(terminal.line().find("0.4 s left") != std::string::npos);  // 50 in 0.5 s, 40 to go
  progress.advance(40);
  CHECK(terminal.line().find("100%") != std::string::npos);
  CHECK(terminal.line().find("left") == std::string::npos);
}

TEST_CASE("the progress line fits the width it is given", "[progress]") {
  FakeTerminal terminal;
  terminal.columns = 40;
  Progress progress = terminal.progress();
  progress.start("rendering a long name of a frame", 10);
  terminal.wait(1);
  progress.advance(1);
  terminal.wait(1);
  progress.advance(1);
  CHECK(terminal.line().size() <= 39);
  progress.finish("wrote out.png");
  CHECK(terminal.text.substr(terminal.text.size() - 14) == "wrote out.png\n");
}

TEST_CASE("over an animation's frames the line also tells the time left for all of them",
          "[progress]") {
  FakeTerminal terminal;
  terminal.columns = 120;
  Progress progress = terminal.progress();
  progress.frames(3);
  progress.start("frame 1/3", 100);
  terminal.wait(2.0);  // one-off costs before the first piece, as for a single frame
  progress.advance(10);
  CHECK(terminal.line().find("all frames") == std::string::npos);
  terminal.wait(1.0);
  progress.advance(50);
  // 50 pieces a second: 40 left of this frame, 240 of all three.
  CHECK(terminal.line().find("0.8 s left, all frames 4.8 s left") != std::string::npos);
  progress.advance(40);
  progress.phase("writing");
  progress.start("frame 2/3", 100);
  terminal.wait(1.0);
  progress.advance(50);
  // 140 pieces in 2 s since the first: 150 to go.
  CHECK(terminal.line().find("all frames 2.1 s left") != std::string::npos);
}

// Every signal that ends clrt (SIGINT, SIGTERM, SIGHUP, SIGQUIT, SIGALRM, SIGPIPE, SIGUSR1,
// SIGUSR2, SIGXFSZ), in the middle of writing the output or of the render, leaves neither the
// temporary nor a partial output, and ends clrt by that signal (a shell reports 128 + its
// number). The write is held open deterministically: CLRT_TEST_HOLD_BEFORE_COMMIT names a FIFO,
// and clrt writes the temporary's path to it and waits there, its image fully written to the
// temporary. A render is signalled once clrt has named its device, which it does after OpenCL
// (and LLVM, whose handlers once swallowed some of these signals) has started.
#include <catch2/catch.hpp>

#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <csignal>
#include <filesystem>
#include <fstream>
#include <regex>
#include <set>
#include <sstream>
#include <string>
#include <thread>

#include "render_support.hpp"
#include "scratch_dir.hpp"
#include "spawn_clrt.hpp"

using namespace clrt::test;
namespace fs = std::filesystem;

namespace {

// Waits until `log` holds `text`; fails the test if clrt ends first.
void wait_for_output(const std::string& log, const std::string& text, ClrtProcess& clrt) {
  for (;;) {
    std::ifstream in(log);
    std::stringstream content;
    content << in.rdbuf();
    if (content.str().find(text) != std::string::npos) return;
    int status = 0;
    if (clrt.ended(status))
      FAIL("clrt ended before it printed '" << text << "', status " << status);
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
}

// SIGQUIT and SIGXFSZ dump core by default: not into the test's folders.
void no_core_dumps() {
  const rlimit none{0, 0};
  REQUIRE(::setrlimit(RLIMIT_CORE, &none) == 0);
}

}  // namespace

TEST_CASE("a signal during the write leaves no temporary and no output", "[cli][signals]") {
  const int signal_number = GENERATE(SIGINT, SIGTERM, SIGHUP, SIGQUIT, SIGALRM, SIGPIPE, SIGUSR1,
                                     SIGUSR2, SIGXFSZ);
  no_core_dumps();
  INFO("signal " << signal_number);
  ScratchDir dir;
  const std::string fifo = dir.file("hold");
  REQUIRE(::mkfifo(fifo.c_str(), 0600) == 0);
  ScratchDir logs;
  ClrtProcess clrt({test_scene("test2.ray"), "-q", "--resolution", "40x24", "-o", dir.file("out.png")},
                   dir.path().string(), {"CLRT_TEST_HOLD_BEFORE_COMMIT=" + fifo}, logs.file("log"));
  const std::string temporary = read_fifo_line(fifo, clrt);
  CHECK(fs::path(temporary).parent_path() == dir.path());
  // The name docs/reliability.md gives, to spot the leftovers of a process killed outright.
  CHECK(std::regex_match(fs::path(temporary).filename().string(),
                         std::regex("\\.clrt-" + std::to_string(clrt.pid()) + "-[0-9]+\\.tmp")));
  CHECK(fs::file_size(temporary) > 0);  // the whole image is in the temporary by now

  REQUIRE(::kill(clrt.pid(), signal_number) == 0);
  const int status = clrt.wait();
  REQUIRE(WIFSIGNALED(status));
  CHECK(WTERMSIG(status) == signal_number);
  CHECK_FALSE(fs::exists(temporary));
  CHECK(dir.entries() == std::set<std::string>{"hold"});
}

TEST_CASE("without the hold the same command writes its output", "[cli][signals]") {
  ScratchDir dir;
  ScratchDir logs;
  ClrtProcess clrt({test_scene("test2.ray"), "-q", "--resolution", "40x24", "-o", dir.file("out.png")},
                   dir.path().string(), {}, logs.file("log"));
  const int status = clrt.wait();
  REQUIRE(WIFEXITED(status));
  CHECK(WEXITSTATUS(status) == 0);
  CHECK(dir.entries() == std::set<std::string>{"out.png"});
}

// SIGINT and SIGTERM during the rounds of samples stop the render after its round and keep
// what it rendered (test_cli_resume.cpp).
TEST_CASE("a signal during the render ends clrt by that signal, leaving nothing",
          "[cli][signals]") {
  const int signal_number =
      GENERATE(SIGHUP, SIGQUIT, SIGALRM, SIGPIPE, SIGUSR1, SIGUSR2, SIGXFSZ);
  INFO("signal " << signal_number);
  no_core_dumps();
  ScratchDir dir;
  ScratchDir logs;
  // Far longer than the signal takes to arrive (tens of seconds on a busy machine): the render
  // cannot finish first.
  ClrtProcess clrt({test_scene("test2.ray"), "--resolution", "2400x2400", "--spp", "64", "-o",
                    dir.file("out.png")},
                   dir.path().string(), {}, logs.file("log"));
  wait_for_output(logs.file("log"), "device ", clrt);
  REQUIRE(::kill(clrt.pid(), signal_number) == 0);
  const int status = clrt.wait();
  REQUIRE(WIFSIGNALED(status));
  CHECK(WTERMSIG(status) == signal_number);
  CHECK(dir.entries().empty());
}

TEST_CASE("a signal ignored from the start, as nohup ignores SIGHUP, stays ignored",
          "[cli][signals]") {
  no_core_dumps();
  ScratchDir dir;
  const std::string fifo = dir.file("hold");
  REQUIRE(::mkfifo(fifo.c_str(), 0600) == 0);
  ScratchDir logs;
  const auto saved = std::signal(SIGHUP, SIG_IGN);  // for the child to inherit
  ClrtProcess clrt({test_scene("test2.ray"), "-q", "--resolution", "40x24", "-o", dir.file("out.png")},
                   dir.path().string(), {"CLRT_TEST_HOLD_BEFORE_COMMIT=" + fifo}, logs.file("log"),
                   {SIGHUP});
  std::signal(SIGHUP, saved);
  read_fifo_line(fifo, clrt);
  // Had SIGHUP been taken, it would end clrt, whichever of the two clrt saw first.
  REQUIRE(::kill(clrt.pid(), SIGHUP) == 0);
  REQUIRE(::kill(clrt.pid(), SIGTERM) == 0);
  const int status = clrt.wait();
  REQUIRE(WIFSIGNALED(status));
  CHECK(WTERMSIG(status) == SIGTERM);
  CHECK(dir.entries() == std::set<std::string>{"hold"});
}

TEST_CASE("a reader that goes away ends clrt by SIGPIPE, as any program in a pipeline",
          "[cli][signals]") {
  ScratchDir dir;
  const std::string status_file = dir.file("status");
  // 600 x 600 PPM is about 1 MB, more than a pipe holds: clrt is still writing when head quits.
  const CommandResult r = run_program(
      "sh", "-c " + quoted("('" CLRT_EXE "' '" + test_scene("test2.ray") +
                           "' -q --resolution 600x600 -o - --format ppm; echo $? >'" +
                           status_file + "') | head -c 1 >/dev/null"));
  CHECK(r.exit_code == 0);
  CHECK(file_bytes(status_file) == std::to_string(128 + SIGPIPE) + "\n");
  CHECK(r.output.empty());
}

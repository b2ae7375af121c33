// SIGINT or SIGTERM in the middle of writing the output leaves neither the temporary nor a
// partial output, and ends clrt by that signal (a shell reports 130 or 143). The write is held
// open deterministically: CLRT_TEST_HOLD_BEFORE_COMMIT names a FIFO, and clrt writes the
// temporary's path to it and waits there, its image fully written to the temporary.
#include <catch2/catch.hpp>

#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <filesystem>
#include <set>
#include <string>

#include "render_support.hpp"
#include "scratch_dir.hpp"
#include "spawn_clrt.hpp"

using namespace clrt::test;
namespace fs = std::filesystem;

namespace {

// Reads the line the held clrt writes to `fifo`; fails the test if clrt ends first.
std::string read_held_temporary(const std::string& fifo, ClrtProcess& clrt) {
  const int fd = ::open(fifo.c_str(), O_RDONLY | O_NONBLOCK);
  REQUIRE(fd >= 0);
  std::string line;
  // The wait has no time limit of its own: it ends when clrt writes, or ends.
  while (line.empty() || line.back() != '\n') {
    pollfd p{fd, POLLIN, 0};
    ::poll(&p, 1, 200);
    char buffer[4096];
    const ssize_t got = ::read(fd, buffer, sizeof buffer);
    if (got > 0) {
      line.append(buffer, static_cast<std::size_t>(got));
      continue;
    }
    int status = 0;
    if (clrt.ended(status)) {
      ::close(fd);
      FAIL("clrt ended before its write was held, status " << status);
    }
  }
  ::close(fd);
  line.pop_back();
  return line;
}

}  // namespace

TEST_CASE("a signal during the write leaves no temporary and no output", "[cli][signals]") {
  const int signal_number = GENERATE(SIGINT, SIGTERM);
  INFO("signal " << signal_number);
  ScratchDir dir;
  const std::string fifo = dir.file("hold");
  REQUIRE(::mkfifo(fifo.c_str(), 0600) == 0);
  ScratchDir logs;
  ClrtProcess clrt({test_scene("test2.ray"), "-q", "--resolution", "40x24", "-o", dir.file("out.png")},
                   dir.path().string(), {"CLRT_TEST_HOLD_BEFORE_COMMIT=" + fifo}, logs.file("log"));
  const std::string temporary = read_held_temporary(fifo, clrt);
  CHECK(fs::path(temporary).parent_path() == dir.path());
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

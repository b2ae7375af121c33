// clrt --preview against viewers that misbehave, stood in for by scripts named clrt-view beside a
// copy of clrt (which starts the clrt-view beside its own executable): one that never answers
// and ignores SIGTERM, as a viewer blocked on a display that accepted the connection and stalled
// does; and one that opens its "window" and then stops reading. Neither may hold the render: the
// image is written whole and clrt exits 0, with a warning.
#include <catch2/catch.hpp>

#include <sys/wait.h>

#include <csignal>
#include <cstdlib>
#include <filesystem>
#include <string>

#include "image/image.hpp"
#include "render_support.hpp"
#include "scratch_dir.hpp"

using namespace clrt;
using namespace clrt::test;

namespace {

// A copy of clrt in `dir` with `script` as the clrt-view beside it.
std::string clrt_with_viewer(const ScratchDir& dir, const std::string& script) {
  const std::string clrt = dir.file("clrt");
  std::filesystem::copy_file(CLRT_EXE, clrt);
  const std::string viewer = dir.write("clrt-view", script);
  std::filesystem::permissions(viewer, std::filesystem::perms::owner_all);
  return clrt;
}

// Runs `clrt args`, ended by `timeout` if it hangs (status 124); standard error to err.txt.
int run_bounded(const ScratchDir& dir, const std::string& clrt, const std::string& args) {
  const std::string command = "timeout 180 " + quoted(clrt) + " " + args + " 2>" +
                              quoted(dir.file("err.txt"));
  const int raw = std::system(command.c_str());
  return WIFEXITED(raw) ? WEXITSTATUS(raw) : -1;
}

// The fake viewer's process, recorded in pid.txt, ended.
void end_fake_viewer(const ScratchDir& dir) {
  const std::string pid = file_bytes(dir.file("pid.txt"));
  if (!pid.empty()) kill(std::stoi(pid), SIGKILL);
}

}  // namespace

TEST_CASE("the preview: a viewer that never answers and ignores SIGTERM is killed, and the render "
          "written",
          "[cli][preview]") {
  ScratchDir dir;
  const std::string clrt = clrt_with_viewer(
      dir, "#!/bin/sh\ntrap '' TERM\necho $$ > '" + dir.file("pid.txt") + "'\nexec sleep 600\n");
  const std::string out = dir.file("out.png");
  const int status = run_bounded(
      dir, clrt, quoted(test_scene("test2.ray")) + " --resolution 16x8 --preview -o " + quoted(out));
  const std::string err = file_bytes(dir.file("err.txt"));
  end_fake_viewer(dir);
  INFO(err);
  CHECK(status == 0);
  CHECK(err.find("clrt: warning: --preview: clrt-view could not open a window; rendering "
                 "without it") != std::string::npos);
  CHECK(std::filesystem::exists(out));
}

TEST_CASE("the preview: a viewer that stops reading does not hold the render", "[cli][preview]") {
  ScratchDir dir;
  // It takes the 16-byte header, answers that its window is open, and reads nothing more.
  const std::string clrt = clrt_with_viewer(
      dir, "#!/bin/sh\necho $$ > '" + dir.file("pid.txt") +
               "'\nhead -c 16 >/dev/null\nprintf R >&0\nexec sleep 600\n");
  const std::string out = dir.file("out.png");
  // 1600x1200 pixels stream 23 MB of floats, more than the socket and the 16 MiB queue hold.
  const int status =
      run_bounded(dir, clrt,
                  quoted(test_scene("test2.ray")) +
                      " --resolution 1600x1200 --mode cast --preview -o " + quoted(out));
  const std::string err = file_bytes(dir.file("err.txt"));
  end_fake_viewer(dir);
  INFO(err);
  CHECK(status == 0);
  CHECK(err.find("clrt: warning: --preview: clrt-view fell behind; ") != std::string::npos);
  CHECK(err.find(" bands were not shown (the image written is whole)") != std::string::npos);
  REQUIRE(std::filesystem::exists(out));
  CHECK(read_image(out).width == 1600);
}

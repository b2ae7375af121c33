// clrt's image output options: -o - with --format, --format for a file, --exr-pixel; outputs
// that are devices, FIFOs or links, --no-write, long names, and the exit status of outputs that
// cannot be written.
#include <sys/stat.h>
#include <sys/sysmacros.h>
#include <unistd.h>

#include <algorithm>
#include <catch2/catch.hpp>
#include <filesystem>
#include <string>

#include "image/image.hpp"
#include "image/image_info.hpp"
#include "run_tool.hpp"
#include "skip_test.hpp"

using namespace clrt::test;
using Catch::Matchers::Contains;

namespace {

const std::string kSceneFile = quoted(CLRT_SOURCE_DIR "/scenes/test2.ray");
const std::string kScene = kSceneFile + " -q --resolution 40x24";

ToolResult run_clrt(const ScratchDir& dir, const std::string& args) {
  return run_tool(dir, CLRT_EXE, kScene + " " + args);
}

}  // namespace

TEST_CASE("clrt -o - writes the image to standard output in the --format given",
          "[cli][output]") {
  ScratchDir dir;
  for (const char* format : {"png", "ppm", "pfm", "fsf", "exr"}) {
    INFO(format);
    const std::string file = dir.file(std::string("file.") + format);
    REQUIRE(run_clrt(dir, "-o " + quoted(file)).status == 0);
    const ToolResult piped = run_clrt(dir, std::string("-o - --format ") + format);
    CHECK(piped.status == 0);
    CHECK(piped.out == read_bytes(file));
  }
  // Statistics go to standard error when standard output holds the image.
  const ToolResult stats = run_clrt(dir, "-o - --format ppm --stats");
  CHECK(stats.status == 0);
  CHECK(stats.out == read_bytes(dir.file("file.ppm")));
  CHECK_FALSE(stats.err.empty());
}

TEST_CASE("clrt --format names the format of a file, whatever its name", "[cli][output]") {
  ScratchDir dir;
  REQUIRE(run_clrt(dir, "-o " + quoted(dir.file("a.pfm"))).status == 0);
  REQUIRE(run_clrt(dir, "-o " + quoted(dir.file("render.out")) + " --format pfm").status == 0);
  CHECK(read_bytes(dir.file("render.out")) == read_bytes(dir.file("a.pfm")));
  const ToolResult default_name =
      run_tool(dir, "sh", "-c " + quoted("cd " + dir.path().string() + " && '" CLRT_EXE "' " +
                                         CLRT_SOURCE_DIR "/scenes/test2.ray -q --resolution "
                                                         "40x24 --format exr"));
  CHECK(default_name.status == 0);
  CHECK(clrt::read_image_info(dir.file("test2.exr")).format == clrt::ImageFormat::Exr);
}

TEST_CASE("clrt writes half EXR by default and float EXR with --exr-pixel float",
          "[cli][output]") {
  ScratchDir dir;
  const std::string pfm = dir.file("a.pfm"), half = dir.file("h.exr"), full = dir.file("f.exr");
  REQUIRE(run_clrt(dir, "-o " + quoted(pfm)).status == 0);
  REQUIRE(run_clrt(dir, "-o " + quoted(half)).status == 0);
  REQUIRE(run_clrt(dir, "-o " + quoted(full) + " --exr-pixel float").status == 0);
  const clrt::FloatImage rendered = clrt::read_pfm(pfm);
  CHECK(clrt::read_exr(full).rgb == rendered.rgb);
  const std::string reference = dir.file("reference.exr");
  clrt::write_image(reference, rendered);
  CHECK(read_bytes(half) == read_bytes(reference));
  CHECK(clrt::read_image_info(half).samples == "16-bit float (half)");
}

TEST_CASE("clrt warns once when a half EXR stores values beyond the largest half as infinity",
          "[cli][output]") {
  // A red background of 1e5: every pixel the sphere leaves uncovered overflows in R alone.
  ScratchDir dir;
  const std::string scene = dir.file("bright.ray"), half = dir.file("h.exr");
  write_bytes(scene, bytes_of("eye 0 0 5\nlookat 0 0 0\nup 0 1 0\nfov 60\n"
                              "background 100000 0 0\nsphere\nlight 1 1 1 ambient\n"));
  const ToolResult result =
      run_tool(dir, CLRT_EXE, quoted(scene) + " -q --resolution 8x8 -o " + quoted(half));
  REQUIRE(result.status == 0);
  CHECK_THAT(result.err, Contains("clrt: warning: " + half + ": ") &&
                             Contains(" of the 192 samples are beyond 65504, the largest half float"));
  CHECK(std::count(result.err.begin(), result.err.end(), '\n') == 1);
  const ToolResult full = run_tool(
      dir, CLRT_EXE, quoted(scene) + " -q --resolution 8x8 --exr-pixel float -o " + quoted(half));
  REQUIRE(full.status == 0);
  CHECK(full.err.empty());
}

TEST_CASE("clrt refuses -o - without --format and a --format its extension contradicts, at once",
          "[cli][output]") {
  ScratchDir dir;
  ToolResult result = run_clrt(dir, "-o -");
  CHECK(result.status == 2);
  CHECK_THAT(result.err, Contains("--format"));
  CHECK(result.out.empty());
  result = run_clrt(dir, "-o " + quoted(dir.file("out.png")) + " --format exr");
  CHECK(result.status == 2);
  CHECK_THAT(result.err, Contains("clrt: error: ") && Contains("names png"));
  CHECK(run_clrt(dir, "-o - --format gif").status == 2);
  CHECK(run_clrt(dir, "-o " + quoted(dir.file("o.exr")) + " --exr-pixel double").status == 2);
  CHECK(dir.entries() == std::set<std::string>{"stdout.bin", "stderr.txt"});
}

namespace {

struct stat stat_of(const std::string& path) {
  struct stat info {};
  REQUIRE(::stat(path.c_str(), &info) == 0);
  return info;
}

// clrt run with `args` in `dir` as its working directory.
ToolResult run_clrt_in(const ScratchDir& dir, const std::string& args) {
  const std::string command =
      "cd " + dir.path().string() + " && '" CLRT_EXE "' " + kScene + " " + args;
  return run_tool(dir, "sh", "-c " + quoted(command));
}

}  // namespace

TEST_CASE("clrt -o /dev/null renders and leaves /dev/null a device", "[cli][output]") {
  const struct stat before = stat_of("/dev/null");
  REQUIRE(S_ISCHR(before.st_mode));
  ScratchDir dir;
  for (const char* format : {"", " --format exr"}) {
    INFO(format);
    const ToolResult result = run_clrt(dir, std::string("-o /dev/null") + format);
    CHECK(result.status == 0);
    CHECK(result.err.empty());
    const struct stat after = stat_of("/dev/null");
    CHECK(S_ISCHR(after.st_mode));
    CHECK(after.st_rdev == before.st_rdev);
  }
}

TEST_CASE("clrt writes straight through a character device of its own", "[cli][output]") {
  if (::geteuid() != 0) CLRT_SKIP_TEST("mknod needs root");
  ScratchDir dir;
  const std::string device = dir.file("null");
  REQUIRE(::mknod(device.c_str(), S_IFCHR | 0666, makedev(1, 3)) == 0);
  CHECK(run_clrt(dir, "-o " + quoted(device)).status == 0);
  CHECK(S_ISCHR(stat_of(device).st_mode));
  CHECK(dir.entries() == std::set<std::string>{"null", "stdout.bin", "stderr.txt"});
}

TEST_CASE("clrt writes straight through a FIFO to its reader", "[cli][output]") {
  ScratchDir dir;
  const std::string fifo = dir.file("fifo"), received = dir.file("received.ppm");
  REQUIRE(::mkfifo(fifo.c_str(), 0600) == 0);
  const ToolResult result = run_tool(
      dir, "sh",
      "-c " + quoted("cat '" + fifo + "' >'" + received + "' & '" CLRT_EXE "' " + kScene +
                     " --format ppm -o '" + fifo + "'; status=$?; wait; exit $status"));
  CHECK(result.status == 0);
  REQUIRE(run_clrt(dir, "-o " + quoted(dir.file("file.ppm"))).status == 0);
  CHECK(read_bytes(received) == read_bytes(dir.file("file.ppm")));
  CHECK(S_ISFIFO(stat_of(fifo).st_mode));
}

TEST_CASE("clrt -o /proc/self/fd/1 writes to whatever standard output is, a pipe or a file",
          "[cli][output]") {
  ScratchDir dir;
  REQUIRE(run_clrt(dir, "-o " + quoted(dir.file("file.ppm"))).status == 0);
  const Bytes expected = read_bytes(dir.file("file.ppm"));
  // A link the kernel follows to a pipe that has no name: written straight through.
  const ToolResult piped =
      run_tool(dir, "sh", "-c " + quoted("'" CLRT_EXE "' " + kScene +
                                         " --format ppm -o /proc/self/fd/1 | cat"));
  CHECK(piped.status == 0);
  CHECK(piped.out == expected);
  // A link to a file (run_tool's stdout.bin), replaced whole as any file.
  const ToolResult file = run_clrt(dir, "--format ppm -o /proc/self/fd/1");
  CHECK(file.status == 0);
  CHECK(file.out == expected);
}

TEST_CASE("clrt -o LINK replaces the link's target and leaves the link", "[cli][output]") {
  ScratchDir dir;
  std::filesystem::create_directory(dir.file("renders"));
  std::filesystem::create_symlink("renders/latest.ppm", dir.file("out.ppm"));
  REQUIRE(run_clrt(dir, "-o " + quoted(dir.file("out.ppm"))).status == 0);
  REQUIRE(run_clrt(dir, "-o " + quoted(dir.file("out.ppm"))).status == 0);  // replacing it
  CHECK(std::filesystem::is_symlink(dir.file("out.ppm")));
  CHECK(clrt::read_ppm(dir.file("renders/latest.ppm")).width == 40);
  CHECK(std::distance(std::filesystem::directory_iterator(dir.file("renders")),
                      std::filesystem::directory_iterator()) == 1);
}

TEST_CASE("clrt --no-write and -o none render and write nothing, -o '' is a usage error",
          "[cli][output]") {
  ScratchDir dir;
  for (const char* args : {"--no-write", "-o none", "--no-write --stats", "--frames 2 -o none"}) {
    INFO(args);
    const ToolResult result = run_clrt_in(dir, args);
    CHECK(result.status == 0);
    CHECK(result.err.empty());
  }
  CHECK_THAT(run_clrt_in(dir, "--no-write --stats").out_text(), Contains("rays:"));
  const ToolResult empty = run_clrt_in(dir, "-o \"\"");
  CHECK(empty.status == 2);
  CHECK_THAT(empty.err, Contains("clrt: error: ") && Contains("empty"));
  CHECK(dir.entries() == std::set<std::string>{"stdout.bin", "stderr.txt"});
}

TEST_CASE("clrt writes an output whose name is as long as the folder allows", "[cli][output]") {
  ScratchDir dir;
  const long name_max = ::pathconf(dir.path().c_str(), _PC_NAME_MAX);
  const std::string name = std::string(static_cast<std::size_t>(name_max) - 4, 'n') + ".png";
  CHECK(run_clrt(dir, "-o " + quoted(dir.file(name))).status == 0);
  CHECK(clrt::read_png(dir.file(name)).width == 40);
  const ToolResult longer = run_clrt(dir, "-o " + quoted(dir.file("n" + name)));
  CHECK(longer.status == 2);
  CHECK_THAT(longer.err, Contains("more than the"));
  CHECK(dir.entries() == std::set<std::string>{name, "stdout.bin", "stderr.txt"});
}

TEST_CASE("clrt's exit status for outputs: 2 when refused before any work, 1 when the write fails",
          "[cli][output]") {
  ScratchDir dir;
  const ToolResult proc = run_clrt(dir, "-o /proc/clrt-output-test.png");
  CHECK(proc.status == 2);
  CHECK_THAT(proc.err, Contains("clrt: error: cannot write /proc/clrt-output-test.png: "));
  CHECK_THAT(proc.err, !Contains(".tmp"));
  // A file system without room for uncompressed frames (67 MB each in FSF, 201 MB in PFM; 13 and
  // 40 TB in all), known before the render: an animation in one file, or as numbered files.
  for (const char* name : {"huge.fsf", "huge.pfm"}) {
    const ToolResult no_room =
        run_tool(dir, CLRT_EXE, kSceneFile + " -q --resolution 4096x4096 --frames 200000 -o " +
                                    quoted(dir.file(name)));
    CHECK(no_room.status == 1);
    CHECK_THAT(no_room.err, Contains(name) && Contains("free"));
  }
  // /dev/full takes the open and refuses the bytes: only the write finds out.
  const ToolResult full = run_clrt(dir, "-o /dev/full");
  CHECK(full.status == 1);
  CHECK_THAT(full.err, Contains("cannot write /dev/full: No space left on device"));
  CHECK(S_ISCHR(stat_of("/dev/full").st_mode));
  CHECK(dir.entries() == std::set<std::string>{"stdout.bin", "stderr.txt"});
}

TEST_CASE("clrt over an existing file: a read-only one is refused for an ordinary user, any "
          "other keeps its mode",
          "[cli][output]") {
  ScratchDir dir;
  REQUIRE(::chmod(dir.path().c_str(), 0777) == 0);
  const std::string ro = dir.write("ro.png", "not replaced");
  REQUIRE(::chmod(ro.c_str(), 0444) == 0);
  // Root writes a read-only file with `>` and may replace it: the refusal is an ordinary
  // user's, so as root the test runs clrt as nobody through setpriv.
  std::string as_user = quoted(CLRT_EXE);
  if (::geteuid() == 0) {
    if (std::system("setpriv --version >/dev/null 2>&1") != 0)
      CLRT_SKIP_TEST("running as root without setpriv to become an ordinary user");
    REQUIRE(::chown(ro.c_str(), 65534, 65534) == 0);
    as_user = "--reuid=65534 --regid=65534 --clear-groups " + as_user;
  }
  const ToolResult refused = run_tool(dir, ::geteuid() == 0 ? "setpriv" : "env",
                                      as_user + " " + kScene + " -o " + quoted(ro));
  CHECK(refused.status == 2);
  CHECK(refused.err ==
        "clrt: error: cannot write " + ro + ": it is read-only to you (mode 0444)\n");
  CHECK(read_bytes(ro) == bytes_of("not replaced"));
  const std::string own = dir.write("own.png", "replaced");
  REQUIRE(::chmod(own.c_str(), 0600) == 0);
  REQUIRE(run_clrt(dir, "-o " + quoted(own)).status == 0);
  CHECK(clrt::read_image_info(own).width == 40);
  struct stat info {};
  REQUIRE(::stat(own.c_str(), &info) == 0);
  CHECK((info.st_mode & 07777) == 0600);
}

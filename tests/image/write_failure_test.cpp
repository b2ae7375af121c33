// Failed writes leave no file and no temporary behind, and never damage the file already at the
// path. The tests run as root, where permissions stop nothing, so failures come from paths that
// cannot work for anyone and from resource limits, which bind root too.
#include <sys/resource.h>
#include <sys/stat.h>

#include <catch2/catch.hpp>
#include <csignal>
#include <filesystem>
#include <functional>
#include <string>

#include "image/image.hpp"
#include "test_files.hpp"

using Catch::Matchers::Contains;
using clrt::ImageError;
using clrt::Rgba8Image;
using namespace clrt::test;
using Entries = std::set<std::string>;

namespace {

const Rgba8Image kTwoPixels{2, 1, {{1, 2, 3, 255, 4, 5, 6, 255}}};

// Runs `write` with the soft limit of `resource` lowered to `limit`, then restores it before
// anything else (Catch2 included) needs files again. A write past RLIMIT_FSIZE raises SIGXFSZ,
// which is ignored meanwhile so that write() fails with EFBIG instead of killing the test.
std::string error_under_limit(int resource, rlim_t limit, const std::function<void()>& write) {
  rlimit saved{};
  REQUIRE(::getrlimit(resource, &saved) == 0);
  rlimit lowered = saved;
  lowered.rlim_cur = limit;
  const auto old_handler = std::signal(SIGXFSZ, SIG_IGN);
  REQUIRE(::setrlimit(resource, &lowered) == 0);
  const std::string message = error_of(write);
  const int restored = ::setrlimit(resource, &saved);
  std::signal(SIGXFSZ, old_handler);
  REQUIRE(restored == 0);
  return message;
}

}  // namespace

TEST_CASE("a write into a directory that does not exist fails and creates nothing",
          "[image][write]") {
  ScratchDir dir;
  for (const char* name : {"a.fsf", "a.png", "a.ppm", "a.pfm", "a.exr"}) {
    const std::string path = dir.file(std::string("missing/") + name);
    CHECK_THAT(error_of([&] { clrt::write_image(path, kTwoPixels); }),
               Contains(path) && Contains("No such file"));
  }
  CHECK(dir.entries().empty());
}

TEST_CASE("a write over an existing directory fails and leaves no temporary", "[image][write]") {
  ScratchDir dir;
  const std::string path = dir.file("out.fsf");
  std::filesystem::create_directory(path);
  CHECK_THAT(error_of([&] { clrt::write_image(path, kTwoPixels); }),
             Contains(path) && Contains("rename"));
  CHECK(dir.entries() == Entries{"out.fsf"});
  CHECK(std::filesystem::is_directory(path));
}

TEST_CASE("a write into /proc fails, naming the path", "[image][write]") {
  const std::string path = "/proc/clrt-image-test.png";
  CHECK_THAT(error_of([&] { clrt::write_image(path, kTwoPixels); }), Contains(path));
  CHECK_FALSE(std::filesystem::exists(path));
}

TEST_CASE("a failed write leaves the previous file intact and no temporary", "[image][write]") {
  ScratchDir dir;
  const std::string path = dir.file("out.fsf");
  clrt::write_image(path, kTwoPixels);
  const Bytes first = read_bytes(path);
  const Rgba8Image second{4, 4, {Bytes(64, 9)}};

  SECTION("failing mid-write: the file size limit stops the temporary after 20 bytes") {
    const std::string message =
        error_under_limit(RLIMIT_FSIZE, 20, [&] { clrt::write_image(path, second); });
    CHECK_THAT(message, Contains(path) && Contains("File too large"));
  }
  SECTION("failing to create the temporary: no file descriptor may be opened") {
    const std::string message =
        error_under_limit(RLIMIT_NOFILE, 0, [&] { clrt::write_image(path, second); });
    CHECK_THAT(message,
               Contains(path) && Contains("cannot create a file in") &&
                   Contains("Too many open files"));
  }
  CHECK(read_bytes(path) == first);
  CHECK(dir.entries() == Entries{"out.fsf"});

  clrt::write_image(path, second);
  CHECK(clrt::read_fsf(path).frames == second.frames);
  CHECK(dir.entries() == Entries{"out.fsf"});
}

TEST_CASE("a new file gets the permissions the umask allows, like any created file",
          "[image][write]") {
  ScratchDir dir;
  const std::string path = dir.file("out.ppm");
  const mode_t old_mask = ::umask(022);
  clrt::write_image(path, kTwoPixels);
  ::umask(old_mask);
  struct stat info {};
  REQUIRE(::stat(path.c_str(), &info) == 0);
  CHECK((info.st_mode & 0777) == 0644);
}

TEST_CASE("an unknown extension or an invalid image is refused before any file is touched",
          "[image][write]") {
  ScratchDir dir;
  const std::string unknown = dir.file("out.jpg");
  CHECK_THAT(error_of([&] { clrt::write_image(unknown, kTwoPixels); }),
             Contains(unknown) && Contains(".jpg") && Contains(".fsf, .png, .ppm, .pfm, .exr"));
  CHECK_THAT(error_of([&] { clrt::write_image(dir.file("noext"), kTwoPixels); }),
             Contains("no extension"));
  CHECK_THAT(error_of([&] {
               clrt::write_image(dir.file("a.fsf"), Rgba8Image{2, 2, {{1, 2, 3, 4}}});
             }),
             Contains("a.fsf") && Contains("frame 0"));
  CHECK_THAT(error_of([&] {
               clrt::write_image(dir.file("a.png"), Rgba8Image{1, 1, {}});
             }),
             Contains("no frames"));
  CHECK_THAT(error_of([&] {
               clrt::write_image(dir.file("a.pfm"), clrt::FloatImage{1, 1, {0.5f}});
             }),
             Contains("RGB array"));
  CHECK_THAT(error_of([&] {
               clrt::write_image(dir.file("a.exr"), clrt::FloatImage(2, 1, {0, 0, 0, 0, 0, 0},
                                                                     clrt::Placement{3, 0, 4, 1}));
             }),
             Contains("a.exr") && Contains("does not fit in its 4x1 frame"));
  CHECK(dir.entries().empty());
}

TEST_CASE("format_from_path reads the extension case-insensitively", "[image][write]") {
  using clrt::ImageFormat;
  CHECK(clrt::format_from_path("a/b.fsf") == ImageFormat::Fsf);
  CHECK(clrt::format_from_path("B.PnG") == ImageFormat::Png);
  CHECK(clrt::format_from_path("x.y.PPM") == ImageFormat::Ppm);
  CHECK(clrt::format_from_path("out.pfm") == ImageFormat::Pfm);
  CHECK(clrt::format_from_path("out.Exr") == ImageFormat::Exr);
  CHECK_THROWS_AS(clrt::format_from_path("dir.png/file"), ImageError);
  CHECK_THROWS_AS(clrt::format_from_path("a.fsf.bak"), ImageError);
  CHECK_FALSE(clrt::format_of_extension("a.fsf.bak"));
}

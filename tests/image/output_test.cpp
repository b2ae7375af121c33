// Writing to a descriptor (standard output for `-o -`) and choosing an output's format.
#include <fcntl.h>
#include <unistd.h>

#include <catch2/catch.hpp>
#include <cstdlib>
#include <functional>
#include <iostream>
#include <string>

#include "image/image.hpp"
#include "test_files.hpp"

using clrt::FloatImage;
using clrt::ImageError;
using clrt::ImageFormat;
using Catch::Matchers::Contains;
using namespace clrt::test;

namespace {

const FloatImage kTile(3, 2, {0.1f, 0.2f, 0.3f, 1.5f, -1.0f, 0.5f, 0.0f, 0.7f, 0.9f, 0.25f, 1.0f,
                              0.75f, 0.3f, 0.6f, 0.9f, 2.0f, 0.01f, 0.02f},
                       clrt::Placement{4, 1, 10, 5});

// Everything written to a pipe's write end while `write` runs, read back after it closed.
Bytes through_pipe(const std::function<void(int)>& write) {
  int ends[2];
  REQUIRE(::pipe(ends) == 0);
  write(ends[1]);  // the images here fit in the pipe's buffer
  ::close(ends[1]);
  Bytes bytes;
  std::uint8_t buffer[4096];
  ssize_t got;
  while ((got = ::read(ends[0], buffer, sizeof buffer)) > 0)
    bytes.insert(bytes.end(), buffer, buffer + got);
  ::close(ends[0]);
  return bytes;
}

// Standard output is `fd` for the scope.
class StdoutAs {
 public:
  explicit StdoutAs(int fd) : saved_(::dup(STDOUT_FILENO)) {
    std::cout.flush();
    ::dup2(fd, STDOUT_FILENO);
  }
  ~StdoutAs() {
    ::dup2(saved_, STDOUT_FILENO);
    ::close(saved_);
  }

 private:
  int saved_;
};

}  // namespace

TEST_CASE("a pipe gets the same bytes as a file, in every format", "[image][output]") {
  ScratchDir dir;
  for (const char* name : {"fsf", "png", "ppm", "pfm", "exr"}) {
    INFO(name);
    const ImageFormat format = clrt::format_from_name(name);
    const std::string path = dir.file(std::string("a.") + name);
    clrt::write_image(path, kTile);
    CHECK(through_pipe([&](int fd) { clrt::write_image_to_fd(fd, format, kTile); }) ==
          read_bytes(path));
  }
  const std::string exr = dir.file("f.exr");
  clrt::write_image(exr, kTile, {clrt::ExrPixel::Float});
  CHECK(through_pipe([&](int fd) {
          clrt::write_image_to_fd(fd, ImageFormat::Exr, kTile, {clrt::ExrPixel::Float});
        }) == read_bytes(exr));
}

TEST_CASE("resolve_output: - is standard output and needs a format that is not a terminal's",
          "[image][output]") {
  CHECK_THROWS_WITH(clrt::resolve_output("-", std::nullopt), Contains("needs the image format"));
  SECTION("a pipe takes the image") {
    const Bytes piped = through_pipe([](int fd) {
      const StdoutAs redirect(fd);
      const clrt::ImageOutput output = clrt::resolve_output("-", ImageFormat::Ppm);
      CHECK(output.is_stdout());
      clrt::write_image(output, kTile);
    });
    CHECK(std::string(piped.begin(), piped.begin() + 11) == "P6\n3 2\n255\n");
    CHECK(piped.size() == 11 + 18);
  }
  SECTION("a terminal is refused") {
    const int master = ::posix_openpt(O_RDWR | O_NOCTTY);
    REQUIRE(master >= 0);
    REQUIRE(::grantpt(master) == 0);
    REQUIRE(::unlockpt(master) == 0);
    const int terminal = ::open(::ptsname(master), O_RDWR | O_NOCTTY);
    REQUIRE(terminal >= 0);
    {
      const StdoutAs redirect(terminal);
      CHECK_THROWS_WITH(clrt::resolve_output("-", ImageFormat::Png), Contains("terminal"));
    }
    ::close(terminal);
    ::close(master);
  }
}

TEST_CASE("resolve_output: a file's format is --format or its extension, never both differing",
          "[image][output]") {
  CHECK(clrt::resolve_output("out.exr", std::nullopt).format == ImageFormat::Exr);
  CHECK(clrt::resolve_output("out.PNG", ImageFormat::Png).format == ImageFormat::Png);
  CHECK(clrt::resolve_output("out.image", ImageFormat::Pfm).format == ImageFormat::Pfm);
  CHECK(clrt::resolve_output("out", ImageFormat::Fsf).format == ImageFormat::Fsf);
  CHECK_THROWS_WITH(clrt::resolve_output("out.png", ImageFormat::Exr),
                    Contains("out.png") && Contains("names png") && Contains("exr"));
  CHECK_THROWS_WITH(clrt::resolve_output("out.jpg", std::nullopt), Contains(".jpg"));
  CHECK_THROWS_WITH(clrt::format_from_name("jpeg"), Contains("fsf, png, ppm, pfm, exr"));
  CHECK(clrt::format_from_name("EXR") == ImageFormat::Exr);
}

TEST_CASE("a descriptor that cannot be written fails, naming it", "[image][output]") {
  int ends[2];
  REQUIRE(::pipe(ends) == 0);
  ::close(ends[0]);
  ::close(ends[1]);
  CHECK_THROWS_WITH(clrt::write_image_to_fd(ends[1], ImageFormat::Ppm, kTile),
                    Contains("file descriptor " + std::to_string(ends[1])) &&
                        Contains("Bad file descriptor"));
}

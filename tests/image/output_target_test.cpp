// Outputs that are not plain new files: devices and FIFOs are written straight through (a
// rename would replace them by a regular file), a link has its target replaced and stays a
// link, and every name a folder allows can be written (the temporary's name is short).
#include <cerrno>
#include <cstring>
#include <sys/stat.h>
#include <sys/sysmacros.h>
#include <unistd.h>

#include <catch2/catch.hpp>
#include <filesystem>
#include <string>
#include <thread>

#include "image/image.hpp"
#include "image/output_target.hpp"
#include "skip_test.hpp"
#include "test_files.hpp"

using Catch::Matchers::Contains;
using clrt::Rgba8Image;
using namespace clrt::test;
using Entries = std::set<std::string>;
namespace fs = std::filesystem;

namespace {

const Rgba8Image kImage{2, 1, {{1, 2, 3, 255, 4, 5, 6, 255}}};

struct stat lstat_of(const std::string& path) {
  struct stat info {};
  REQUIRE(::lstat(path.c_str(), &info) == 0);
  return info;
}

// Why check_output_writable() refuses `path`, or "".
std::string refusal(const std::string& path) {
  return error_of([&] { clrt::check_output_writable(path); });
}

}  // namespace

TEST_CASE("a character device is written through and stays a device", "[image][output]") {
  if (::geteuid() != 0) CLRT_SKIP_TEST("mknod needs root");
  ScratchDir dir;
  const std::string device = dir.file("null");
  // A private copy of /dev/null (major 1, minor 3): a regression cannot damage the real one.
  REQUIRE(::mknod(device.c_str(), S_IFCHR | 0666, makedev(1, 3)) == 0);
  CHECK(clrt::find_output_target(device).stream);
  CHECK(clrt::resolve_output(device, std::nullopt).format == clrt::ImageFormat::Png);
  clrt::check_output_writable(device);
  clrt::write_image(device, kImage);
  const struct stat after = lstat_of(device);
  CHECK(S_ISCHR(after.st_mode));
  CHECK(after.st_rdev == makedev(1, 3));
  CHECK(dir.entries() == Entries{"null"});
}

TEST_CASE("a FIFO gets the image its reader reads, and stays a FIFO", "[image][output]") {
  ScratchDir dir;
  const std::string fifo = dir.file("pipe.ppm");
  REQUIRE(::mkfifo(fifo.c_str(), 0600) == 0);
  Bytes received;
  std::thread reader([&] { received = read_bytes(fifo); });
  clrt::write_image(fifo, kImage);
  reader.join();
  clrt::write_image(dir.file("file.ppm"), kImage);
  CHECK(received == read_bytes(dir.file("file.ppm")));
  CHECK(S_ISFIFO(lstat_of(fifo).st_mode));
  CHECK(dir.entries() == Entries{"pipe.ppm", "file.ppm"});
}

TEST_CASE("a link's target is replaced and the link stays a link", "[image][output]") {
  ScratchDir dir;
  fs::create_directory(dir.file("real"));
  SECTION("a relative link to an existing file in another folder") {
    write_bytes(dir.file("real/out.ppm"), bytes_of("old"));
    fs::create_symlink("real/out.ppm", dir.file("out.ppm"));
  }
  SECTION("a chain of links, the last one dangling") {
    fs::create_symlink(dir.file("real/out.ppm"), dir.file("middle.ppm"));
    fs::create_symlink("middle.ppm", dir.file("out.ppm"));
  }
  CHECK(clrt::find_output_target(dir.file("out.ppm")).path == dir.file("real/out.ppm"));
  clrt::write_image(dir.file("out.ppm"), kImage);
  CHECK(S_ISLNK(lstat_of(dir.file("out.ppm")).st_mode));
  CHECK(clrt::read_ppm(dir.file("real/out.ppm")).frames == kImage.frames);
  for (const auto& entry : fs::directory_iterator(dir.file("real")))
    CHECK(entry.path().filename() == "out.ppm");  // no temporary left beside the target
}

TEST_CASE("a loop of links is refused, naming the output", "[image][output]") {
  ScratchDir dir;
  fs::create_symlink("b.png", dir.file("a.png"));
  fs::create_symlink("a.png", dir.file("b.png"));
  CHECK_THROWS_WITH(clrt::find_output_target(dir.file("a.png")),
                    Contains(dir.file("a.png")) && Contains("symbolic links"));
}

TEST_CASE("every name the folder allows can be written, a longer one is refused at once",
          "[image][output]") {
  ScratchDir dir;
  const long name_max = ::pathconf(dir.path().c_str(), _PC_NAME_MAX);
  REQUIRE(name_max > 4);
  const auto name_of = [](long bytes) { return std::string(static_cast<std::size_t>(bytes), 'n'); };
  const std::string longest = dir.file(name_of(name_max - 4) + ".ppm");
  clrt::check_output_writable(longest);
  clrt::write_image(longest, kImage);
  CHECK(clrt::read_ppm(longest).frames == kImage.frames);
  CHECK(dir.entries().size() == 1);
  const std::string too_long = dir.file(name_of(name_max - 3) + ".ppm");
  CHECK_THAT(refusal(too_long), Contains(too_long) && Contains("bytes"));
  CHECK(dir.entries().size() == 1);
}

TEST_CASE("an output that cannot be created is refused before any work, naming the user's path",
          "[image][output]") {
  const std::string proc = "/proc/clrt-output-test.png";
  const std::string message = refusal(proc);
  CHECK_THAT(message, Contains(proc));
  CHECK_THAT(message, !Contains(".tmp"));
  ScratchDir dir;
  CHECK_THAT(refusal(dir.path().string()), Contains("it is a folder"));
  CHECK_THAT(refusal(dir.file("no/such.png")), Contains("no: No such file or directory"));
  CHECK_THAT(refusal(dir.file("fine.png/x.png")), Contains("fine.png: No such file or directory"));
  clrt::check_output_writable(dir.file("fine.png"));
  CHECK(dir.entries().empty());  // the probe is removed again
  const std::string file = dir.write("file.txt", "x");
  CHECK_THAT(refusal(file + "/x.png"), Contains("file.txt is not a folder"));
}

TEST_CASE("a path longer than the system allows is refused at once, as the system says",
          "[image][output]") {
  ScratchDir dir;
  std::string deep = dir.path().string();
  for (int i = 0; i < 20; ++i) deep += "/" + std::string(250, 'd');  // beyond PATH_MAX (4096)
  const std::string path = deep + "/out.png";
  CHECK_THAT(refusal(path), Contains(std::strerror(ENAMETOOLONG)));
  CHECK(dir.entries().empty());
}

TEST_CASE("the bytes an uncompressed image needs at least, and the free bytes", "[image][output]") {
  using clrt::ImageFormat;
  CHECK(clrt::minimum_file_bytes(ImageFormat::Fsf, 10) == 40);
  CHECK(clrt::minimum_file_bytes(ImageFormat::Ppm, 10) == 30);
  CHECK(clrt::minimum_file_bytes(ImageFormat::Pfm, 10) == 120);
  CHECK(clrt::minimum_file_bytes(ImageFormat::Png, 10) == 0);
  CHECK(clrt::minimum_file_bytes(ImageFormat::Exr, 10) == 0);
  ScratchDir dir;
  CHECK(clrt::free_bytes_for(dir.file("out.ppm")) > 0);
}

// clrt's limits through the executable: each request beyond them exits before any work
// with the right code and a message that names the real cause, and writes nothing.
#include <catch2/catch.hpp>

#include <sys/wait.h>
#include <unistd.h>

#include <filesystem>
#include <set>
#include <string>

#include "png_header.hpp"
#include "render_support.hpp"
#include "scratch_dir.hpp"
#include "skip_test.hpp"
#include "spawn_clrt.hpp"

using namespace clrt::test;
namespace fs = std::filesystem;

namespace {

// Runs clrt on `scene` (text written to DIR/s.ray) with `options`; it must exit `code` with
// `message` in its output and leave DIR holding only the scene.
void refuses(const std::string& scene, const std::string& options, int code,
             const std::string& message) {
  ScratchDir dir;
  const std::string path = dir.write("s.ray", scene);
  const CommandResult r = run_clrt(quoted(path) + " -q -o " + quoted(dir.file("out.png")) + " " + options);
  INFO(r.output);
  CHECK(r.exit_code == code);
  CHECK_THAT(r.output, Catch::Contains(message));
  CHECK(dir.entries() == std::set<std::string>{"s.ray"});
}

// Runs clrt on the scene at `path`, writing DIR/out.png, with its address space capped at `kib`
// KiB (ulimit -v).
CommandResult run_clrt_with_address_space(const ScratchDir& dir, const std::string& path, long kib) {
  // Double quotes inside: the whole command is single-quoted for sh -c.
  const std::string clrt = std::string("\"") + CLRT_EXE + "\" -q -o \"" + dir.file("out.png") + "\" \"" + path + "\"";
  return run_program("sh", "-c " + quoted("ulimit -v " + std::to_string(kib) + " && exec " + clrt));
}

}  // namespace

TEST_CASE("the six-line scene whose light samples wrapped in 32 bits exits 2", "[cli][limits]") {
  // It crashed clrt with SIGSEGV: the shade kernel wrote shadow slots past their buffer.
  refuses("resolution 40 40\nsphere\n"
          "light 1 1 1 area -1 3 -1 2 0 0 0 0 2 2147483647\n"
          "light 1 1 1 area -1 3 -1 2 0 0 0 0 2 2147483647\n"
          "light 1 1 1 point 0 3 3\nlight 1 1 1 point 0 3 3\n",
          "", 2, "s.ray:3:38: error: the number of light samples must be a whole number from 1 to 65536");
}

TEST_CASE("image sizes beyond the limits exit 2 before any work", "[cli][limits]") {
  const std::string scene = "sphere\n";
  // 100000x100000 allocated 16.9 GB and ran for minutes.
  refuses(scene, "--resolution 100000x100000", 2,
          "clrt: error: the image size 100000x100000 is beyond the limit: each side must be from 1 to 65536");
  refuses(scene, "--resolution 60000x60000", 2,
          "the image size 60000x60000 is 3600000000 pixels, more than the limit of 268435456");
  // In the file, 65536 x 65537 wrapped in 32 bits and rendered a subset.
  refuses("resolution 65536 65537\nsphere\n", "", 2, "s.ray:1:18: error: the image height must be a whole number");
}

TEST_CASE("a scene's maxdepth has the command line's cap", "[cli][limits]") {
  // Two facing mirrors at this depth ran for about a day.
  refuses("maxdepth 2000000000\nsphere\n", "", 2, "s.ray:1:10: error: maxdepth must be a whole number from 0 to 65536");
  refuses("sphere\n", "--max-depth 65537", 2, "--max-depth");
}

TEST_CASE("/dev/zero as the scene exits 2 without reading it", "[cli][limits]") {
  ScratchDir dir;
  const CommandResult r = run_clrt("/dev/zero -q -o " + quoted(dir.file("out.png")));
  INFO(r.output);
  CHECK(r.exit_code == 2);
  CHECK_THAT(r.output, Catch::Contains("/dev/zero: error: cannot read the scene file (it is not a regular file)"));
  CHECK(dir.entries().empty());
}

TEST_CASE("an output that is an input is refused before any work", "[cli][limits]") {
  ScratchDir dir;
  const std::string scene = "eye 0 0 5\nsphere\nmesh m.ppm\n";
  dir.write("m.ppm", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
  SECTION("the default output of a scene named s.png is the scene") {
    dir.write("s.png", scene);
    ScratchDir logs;
    ClrtProcess clrt({"-q", "s.png"}, dir.path().string(), {}, logs.file("log"));
    const int status = clrt.wait();
    REQUIRE(WIFEXITED(status));
    CHECK(WEXITSTATUS(status) == 2);
    CHECK_THAT(file_bytes(logs.file("log")),
               Catch::Contains("the output s.png is the scene s.png itself; name another output with -o"));
  }
  SECTION("-o names the scene through a hard link") {
    // Refused before the scene is read, as any output with other hard links is.
    dir.write("s.png", scene);
    fs::create_hard_link(dir.file("s.png"), dir.file("link.png"));
    const CommandResult r = run_clrt(quoted(dir.file("s.png")) + " -q -o " + quoted(dir.file("link.png")));
    INFO(r.output);
    CHECK(r.exit_code == 2);
    CHECK_THAT(r.output, Catch::Contains("link.png: it has 2 hard links"));
    CHECK(file_bytes(dir.file("s.png")) == scene);
  }
  SECTION("-o names a mesh") {
    dir.write("s.png", scene);
    const CommandResult r = run_clrt(quoted(dir.file("s.png")) + " -q -o " + quoted(dir.file("m.ppm")));
    INFO(r.output);
    CHECK(r.exit_code == 2);
    CHECK_THAT(r.output, Catch::Contains("is the mesh"));
  }
  CHECK(file_bytes(dir.file("s.png")) == scene);
  CHECK(file_bytes(dir.file("m.ppm")).rfind("v 0 0 0", 0) == 0);
}

TEST_CASE("a scene larger than the memory clrt may take stops loading early, at its line, exit 2",
          "[cli][limits][memory]") {
#if defined(__SANITIZE_ADDRESS__)
  // AddressSanitizer reserves terabytes of address space for its shadow memory, so no build of
  // it starts under ulimit -v.
  CLRT_SKIP_TEST("AddressSanitizer cannot run under ulimit -v");
#endif
  // 6M spheres: 103 MB of text, estimated at 2.5 GiB to load and render (an instance, its
  // geometry and its line); the address space is capped at 2 GiB, so loading must stop part way,
  // with the figures, not on a failed allocation.
  ScratchDir dir;
  std::string text = "resolution 8 8\n";
  for (int i = 0; i < 6000000; ++i) text += "sphere " + std::to_string(i % 1000) + " 0 0 0.5\n";
  const std::string path = dir.write("big.ray", text);
  const CommandResult r = run_clrt_with_address_space(dir, path, 2097152);
  INFO(r.output);
  CHECK(r.exit_code == 2);
  CHECK_THAT(r.output, Catch::Contains(path + ":") &&
                           Catch::Contains(":1: error: loading stopped here: the scene needs ") &&
                           Catch::Contains(" MiB available (RLIMIT_AS, ulimit -v)"));
  CHECK(dir.entries() == std::set<std::string>{"big.ray"});
}

TEST_CASE("a texture image larger than the memory clrt may take is refused from its header, exit 2",
          "[cli][limits][memory][texture]") {
#if defined(__SANITIZE_ADDRESS__)
  CLRT_SKIP_TEST("AddressSanitizer cannot run under ulimit -v");
#endif
  // 16384 x 16384 texels declared: 1 GiB decoded and 1.3 GiB of mip levels twice (host and
  // device), past the 2 GiB address space the run is capped at; the file is a header alone.
  ScratchDir dir;
  dir.write("big.png", png_header(16384, 16384));
  const std::string path = dir.write("big.ray", "resolution 8 8\nsphere\ntexture color image big.png\n");
  const CommandResult r = run_clrt_with_address_space(dir, path, 2097152);
  INFO(r.output);
  CHECK(r.exit_code == 2);
  CHECK_THAT(r.output, Catch::Contains(path + ":3:21: error: cannot use the texture image") &&
                           Catch::Contains(" MiB available (RLIMIT_AS, ulimit -v)"));
  CHECK(dir.entries() == std::set<std::string>{"big.png", "big.ray"});
}

TEST_CASE("an environment image larger than the memory clrt may take is refused from its header, exit 2",
          "[cli][limits][memory][environment]") {
#if defined(__SANITIZE_ADDRESS__)
  CLRT_SKIP_TEST("AddressSanitizer cannot run under ulimit -v");
#endif
  // 16384 x 16384 pixels declared, about 15 GiB with the map's sampling table, in a file of a
  // header alone: refused at its line before a pixel is decoded.
  ScratchDir dir;
  dir.write("sky.png", png_header(16384, 16384));
  const std::string path = dir.write("sky.ray", "resolution 8 8\nenvironment sky.png\nsphere\n");
  const CommandResult r = run_clrt_with_address_space(dir, path, 2097152);
  INFO(r.output);
  CHECK(r.exit_code == 2);
  CHECK_THAT(r.output, Catch::Contains(path + ":2:13: error: cannot read the environment image") &&
                           Catch::Contains("the scene with it would need ") &&
                           Catch::Contains(" MiB available (RLIMIT_AS, ulimit -v)"));
  CHECK(dir.entries() == std::set<std::string>{"sky.png", "sky.ray"});
}

TEST_CASE("an animated FSF as a texture costs its first frame alone", "[cli][limits][memory][texture]") {
#if defined(__SANITIZE_ADDRESS__)
  CLRT_SKIP_TEST("AddressSanitizer cannot run under ulimit -v");
#endif
  // 20 million 1x1 frames, 80 MB: every frame was decoded (1.26 GB, 19 s), and under this limit
  // the run ended in std::bad_alloc.
  ScratchDir dir;
  constexpr std::uint32_t kFrames = 20000000;
  std::string fsf;
  for (std::uint32_t v : {575u, 1u, 1u, kFrames})
    for (int s = 0; s < 32; s += 8) fsf.push_back(static_cast<char>((v >> s) & 0xff));
  fsf.reserve(16 + 4 * std::size_t{kFrames});
  for (std::uint32_t i = 0; i < kFrames; ++i) fsf += i == 0 ? std::string("\xc8\x64\x32\xff", 4) : std::string(4, '\0');
  dir.write("frames.fsf", fsf);
  fsf.resize(16 + 4);
  fsf[12] = 1;  // the same first frame, alone
  fsf[13] = fsf[14] = fsf[15] = 0;
  dir.write("first.fsf", fsf);
  const auto render = [&](const std::string& texture) {
    const std::string path = dir.write("s.ray", "resolution 8 8\nlight 1 1 1 ambient\nmaterial 1 1 1 1 0 0 1 0 0\n"
                                                 "texture color image " + texture + "\nsphere 0 0 -3 1\n");
    const CommandResult r = run_clrt_with_address_space(dir, path, 1572864);
    INFO(r.output);
    CHECK(r.exit_code == 0);
    return clrt::read_png(dir.file("out.png")).frames.at(0);
  };
  const std::vector<std::uint8_t> first = render("first.fsf");
  CHECK(first[4 * (4 * 8 + 4)] > 0);  // the sphere's centre shows the frame's colour
  CHECK(render("frames.fsf") == first);
}

TEST_CASE("a texture is read without a temporary file: TMPDIR is never touched", "[cli][limits][texture]") {
  ScratchDir dir;
  clrt::write_image(dir.file("t.png"), clrt::Rgba8Image(1, 1, {{255, 0, 0, 255}}));
  const std::string path = dir.write("s.ray", "resolution 4 4\nsphere\ntexture color image t.png\n");
  dir.write("not-a-folder", "");
  fs::create_directory(dir.file("empty"));
  // A missing folder and a file named as TMPDIR made a valid texture fail; a folder of its own is
  // left as it was.
  for (const std::string& tmpdir : {dir.file("missing"), dir.file("not-a-folder"), dir.file("empty")}) {
    INFO(tmpdir);
    const CommandResult r =
        run_clrt("-q -o " + quoted(dir.file("out.png")) + " " + quoted(path), "TMPDIR=" + quoted(tmpdir));
    INFO(r.output);
    CHECK(r.exit_code == 0);
  }
  CHECK(fs::is_empty(dir.file("empty")));
  CHECK(!fs::exists(dir.file("missing")));
}

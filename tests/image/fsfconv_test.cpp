// clrt-fsfconv end to end: the built executable, run through the shell.
#include <sys/wait.h>

#include <catch2/catch.hpp>
#include <cstdlib>
#include <string>

#include "image/image.hpp"
#include "test_files.hpp"

using clrt::Rgba8Image;
using namespace clrt::test;
using Catch::Matchers::Contains;

namespace {

struct RunResult {
  int status = -1;
  std::string out, err;
};

// Runs clrt-fsfconv with `args` (already shell-quoted where needed), capturing both streams.
RunResult run_fsfconv(const ScratchDir& dir, const std::string& args) {
  const std::string out_path = dir.file("stdout.txt"), err_path = dir.file("stderr.txt");
  const std::string command =
      "'" CLRT_FSFCONV "' " + args + " >'" + out_path + "' 2>'" + err_path + "'";
  const int raw = std::system(command.c_str());
  REQUIRE(WIFEXITED(raw));
  const Bytes out = read_bytes(out_path), err = read_bytes(err_path);
  return {WEXITSTATUS(raw), std::string(out.begin(), out.end()),
          std::string(err.begin(), err.end())};
}

std::string quoted(const std::string& path) { return "'" + path + "'"; }

// Opaque pixels with distinct channels: PNG and PPM keep them exactly.
const Rgba8Image kAnimation{3,
                            2,
                            {{10, 20, 30, 255, 40, 50, 60, 255, 70, 80, 90, 255,  //
                              1,  2,  3,  255, 4,  5,  6,  255, 7,  8,  9,  255},
                             {200, 201, 202, 255, 203, 204, 205, 255, 206, 207, 208, 255,  //
                              0,   0,   0,   255, 255, 255, 255, 255, 128, 64,  32,  255}}};

}  // namespace

TEST_CASE("clrt-fsfconv: FSF -> PNG -> FSF gives back the same file", "[image][fsfconv]") {
  ScratchDir dir;
  const std::string fsf = dir.file("in.fsf"), png = dir.file("mid.png"),
                    back = dir.file("back.fsf");
  const Rgba8Image still{3, 2, {kAnimation.frames[0]}};
  clrt::write_image(fsf, still);
  REQUIRE(run_fsfconv(dir, quoted(fsf) + " " + quoted(png)).status == 0);
  CHECK(clrt::read_png(png).frames == still.frames);
  REQUIRE(run_fsfconv(dir, quoted(png) + " " + quoted(back)).status == 0);
  CHECK(read_bytes(back) == read_bytes(fsf));
}

TEST_CASE("clrt-fsfconv: PPM both ways and --frame picks a frame", "[image][fsfconv]") {
  ScratchDir dir;
  const std::string anim = dir.file("anim.fsf"), ppm = dir.file("f1.ppm"), fsf = dir.file("f1.fsf");
  clrt::write_image(anim, kAnimation);
  REQUIRE(run_fsfconv(dir, quoted(anim) + " " + quoted(ppm) + " --frame 1").status == 0);
  REQUIRE(run_fsfconv(dir, quoted(ppm) + " " + quoted(fsf)).status == 0);
  const Rgba8Image back = clrt::read_fsf(fsf);
  CHECK(back.width == 3);
  CHECK(back.frames == std::vector<Bytes>{kAnimation.frames[1]});

  const std::string copy = dir.file("copy.fsf");
  REQUIRE(run_fsfconv(dir, quoted(anim) + " " + quoted(copy)).status == 0);
  CHECK(read_bytes(copy) == read_bytes(anim));
}

TEST_CASE("clrt-fsfconv --info prints the header summary", "[image][fsfconv]") {
  ScratchDir dir;
  const std::string anim = dir.file("anim.fsf");
  clrt::write_image(anim, kAnimation);
  const RunResult result = run_fsfconv(dir, "--info " + quoted(anim));
  CHECK(result.status == 0);
  CHECK(result.out == "width: 3\nheight: 2\nframes: 2\nbyte order: little-endian\nbytes: 64\n");
  CHECK(result.err.empty());
}

TEST_CASE("clrt-fsfconv fails with status 1 on bad files and 2 on bad usage", "[image][fsfconv]") {
  ScratchDir dir;
  const std::string anim = dir.file("anim.fsf"), missing = dir.file("missing.fsf"),
                    out = dir.file("out.png");
  clrt::write_image(anim, kAnimation);

  RunResult result = run_fsfconv(dir, quoted(missing) + " " + quoted(out));
  CHECK(result.status == 1);
  CHECK_THAT(result.err, Contains(missing));
  result = run_fsfconv(dir, quoted(anim) + " " + quoted(out) + " --frame 2");
  CHECK(result.status == 1);
  CHECK_THAT(result.err, Contains("no frame 2"));
  result = run_fsfconv(dir, quoted(anim) + " " + quoted(dir.file("out.gif")));
  CHECK(result.status == 1);
  CHECK_THAT(result.err, Contains(".gif"));
  result = run_fsfconv(dir, "--info " + quoted(out));
  CHECK(result.status == 1);

  CHECK(run_fsfconv(dir, "").status == 2);
  CHECK(run_fsfconv(dir, quoted(anim)).status == 2);
  CHECK(run_fsfconv(dir, "--info " + quoted(anim) + " " + quoted(out)).status == 2);
  CHECK(run_fsfconv(dir, quoted(anim) + " " + quoted(out) + " --frame -1").status == 2);
  CHECK(run_fsfconv(dir, "--bogus").status == 2);
  CHECK(dir.entries() == std::set<std::string>{"anim.fsf", "stdout.txt", "stderr.txt"});
}

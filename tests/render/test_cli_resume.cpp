// Stopping a render and going on with --resume (docs/cli.md#stopping-and-resuming-a-render): a
// first SIGINT or SIGTERM during the rounds of samples ends the render after its round, writes
// the image of the samples taken (its count recorded) and the state beside it, and ends clrt by
// that signal; a second ends clrt at once; --resume goes on to the bytes of a render that never
// stopped, adds samples to a finished one, and refuses a state of another scene or options.
// The stop is deterministic: CLRT_TEST_HOLD_AFTER_ROUND=K:FIFO makes clrt write to the FIFO
// after its K-th round and wait there for the signal.
//
// The renders: path mode (whose Sobol samples do not depend on the total, so samples can be
// added), 32x32 pixels, a wavefront of 1024 rays on one lane: 4 samples per pixel a round.
#include <catch2/catch.hpp>

#include <signal.h>
#include <sys/stat.h>
#include <sys/wait.h>

#include <filesystem>
#include <fstream>
#include <set>
#include <string>
#include <vector>

#include "image/image.hpp"
#include "render_support.hpp"
#include "scratch_dir.hpp"
#include "spawn_clrt.hpp"

using namespace clrt;
using namespace clrt::test;
namespace fs = std::filesystem;

namespace {

std::vector<std::string> path_render(const std::string& scene, const std::string& output,
                                     int samples, int wavefront = 1024) {
  return {scene,       "--mode",      "path",
          "--resolution", "32x32",    "--spp",
          std::to_string(samples),    "--wavefront",
          std::to_string(wavefront),  "--lanes",
          "1",         "-o",          output};
}

std::string joined(const std::vector<std::string>& words) {
  std::string line;
  for (const std::string& w : words) line += (line.empty() ? "" : " ") + quoted(w);
  return line;
}

// Runs clrt to the end with `words`; fails the test unless it succeeds.
void render_through(const std::vector<std::string>& words) {
  const CommandResult r = run_clrt(joined(words) + " -q");
  INFO(r.output);
  REQUIRE(r.exit_code == 0);
}

// Starts clrt with `words`, holds it after round `round`, signals it, and returns its wait
// status; its terminal output is left in `log`.
int stopped_render(const std::vector<std::string>& words, unsigned round, int signal_number,
                   const std::string& fifo, const std::string& log,
                   const std::string& working_dir) {
  if (!fs::exists(fifo)) REQUIRE(::mkfifo(fifo.c_str(), 0600) == 0);
  ClrtProcess clrt(words, working_dir,
                   {"CLRT_TEST_HOLD_AFTER_ROUND=" + std::to_string(round) + ":" + fifo}, log);
  CHECK(read_fifo_line(fifo, clrt) == "round " + std::to_string(round));
  REQUIRE(::kill(clrt.pid(), signal_number) == 0);
  return clrt.wait();
}

std::string scene() { return test_scene("path/cornell.ray"); }

}  // namespace

TEST_CASE("a first SIGINT or SIGTERM keeps the rounds done as a valid image, with their count",
          "[cli][signals][resume]") {
  const int signal_number = GENERATE(SIGINT, SIGTERM);
  INFO("signal " << signal_number);
  ScratchDir dir, logs;
  const std::string out = dir.file("out.png");
  const int status = stopped_render(path_render(scene(), out, 64), 2, signal_number,
                                    dir.file("hold"), logs.file("log"), dir.path().string());
  // Ended by the signal: a shell reports 130 for SIGINT, 143 for SIGTERM.
  REQUIRE(WIFSIGNALED(status));
  CHECK(WTERMSIG(status) == signal_number);
  const std::string log = file_bytes(logs.file("log"));
  CHECK(log.find("clrt: stopped: wrote " + out +
                 " with 8/64 samples per pixel; --resume goes on from " + out + ".clrt-resume") !=
        std::string::npos);
  CHECK(dir.entries() == std::set<std::string>{"hold", "out.png", "out.png.clrt-resume"});
  // PNG's text chunk: the keyword, a NUL, the text.
  CHECK(file_bytes(out).find(std::string("tEXtclrt:samples") + '\0' + "8/64") != std::string::npos);
  // Path mode draws sample k whatever the total: the 8 samples are those of an 8-spp render.
  const std::string eight = dir.file("eight.png");
  render_through(path_render(scene(), eight, 8));
  const Rgba8Image stopped = read_image(out), straight = read_image(eight);
  CHECK(stopped.width == 32);
  CHECK(stopped.height == 32);
  CHECK(stopped.frames == straight.frames);
  // A whole render records none.
  CHECK(file_bytes(eight).find("clrt:samples") == std::string::npos);
  const CommandResult piped = run_clrt(joined({scene(), "--mode", "path", "--resolution",
                                               "32x32", "--spp", "8", "-o", "-", "--format",
                                               "png"}) +
                                       " -q");
  CHECK(piped.exit_code == 0);
  CHECK(piped.output.find("IHDR") != std::string::npos);
  CHECK(piped.output.find("clrt:samples") == std::string::npos);  // nor one to standard output
}

TEST_CASE("an EXR stopped early records its sample count as an attribute",
          "[cli][signals][resume]") {
  ScratchDir dir, logs;
  const std::string out = dir.file("out.exr");
  const int status = stopped_render(path_render(scene(), out, 64), 3, SIGINT, dir.file("hold"),
                                    logs.file("log"), dir.path().string());
  REQUIRE(WIFSIGNALED(status));
  // A string attribute: its name, a NUL, its type "string", a NUL, its size, the text.
  CHECK(file_bytes(out).find(std::string("clrt:samples") + '\0' + "string") != std::string::npos);
  CHECK(file_bytes(out).find("12/64") != std::string::npos);
  CHECK(read_exr(out).width == 32);
}

TEST_CASE("a second signal ends clrt at once, writing nothing", "[cli][signals][resume]") {
  ScratchDir dir, logs;
  const std::string fifo = dir.file("hold");
  REQUIRE(::mkfifo(fifo.c_str(), 0600) == 0);
  // Held after round 2, then again with the stopped render's image in its temporary.
  ClrtProcess clrt(path_render(scene(), dir.file("out.png"), 64), dir.path().string(),
                   {"CLRT_TEST_HOLD_AFTER_ROUND=2:" + fifo, "CLRT_TEST_HOLD_BEFORE_COMMIT=" + fifo},
                   logs.file("log"));
  CHECK(read_fifo_line(fifo, clrt) == "round 2");
  REQUIRE(::kill(clrt.pid(), SIGINT) == 0);
  const std::string temporary = read_fifo_line(fifo, clrt);
  CHECK(fs::exists(temporary));
  REQUIRE(::kill(clrt.pid(), SIGINT) == 0);
  const int status = clrt.wait();
  REQUIRE(WIFSIGNALED(status));
  CHECK(WTERMSIG(status) == SIGINT);
  CHECK(dir.entries() == std::set<std::string>{"hold"});
}

TEST_CASE("resuming finishes a stopped render with the bytes of one that never stopped",
          "[cli][resume]") {
  ScratchDir dir, logs;
  const std::string straight = dir.file("straight.png"), out = dir.file("out.png");
  render_through(path_render(scene(), straight, 64));
  std::vector<std::string> words = path_render(scene(), out, 64);
  REQUIRE(WIFSIGNALED(stopped_render(words, 2, SIGINT, dir.file("hold"), logs.file("log"),
                                     dir.path().string())));
  SECTION("at once") {}
  SECTION("stopped again on the way, on other rounds of samples") {
    // A wavefront of 2048 takes 8 samples a round: from 8 to 24 here.
    std::vector<std::string> again = path_render(scene(), out, 64, 2048);
    again.push_back("--resume");
    REQUIRE(WIFSIGNALED(stopped_render(again, 2, SIGTERM, dir.file("hold"), logs.file("log2"),
                                       dir.path().string())));
    CHECK(file_bytes(logs.file("log2")).find("resuming " + out + " from 8/64 spp") !=
          std::string::npos);
    CHECK(file_bytes(logs.file("log2")).find("with 24/64 samples per pixel") != std::string::npos);
  }
  words.push_back("--resume");
  render_through(words);
  CHECK(file_bytes(out) == file_bytes(straight));
  SECTION("a render without --resume leaves no state behind") {
    render_through(path_render(scene(), out, 64));
    CHECK_FALSE(fs::exists(out + ".clrt-resume"));
  }
}

TEST_CASE("resuming with more samples adds samples to a finished render", "[cli][resume]") {
  ScratchDir dir;
  const std::string straight = dir.file("straight.png"), out = dir.file("out.png");
  render_through(path_render(scene(), straight, 64));
  std::vector<std::string> sixteen = path_render(scene(), out, 16);
  sixteen.push_back("--resume");
  render_through(sixteen);
  CHECK(fs::exists(out + ".clrt-resume"));  // kept, for samples to be added
  std::vector<std::string> more = path_render(scene(), out, 64);
  more.push_back("--resume");
  render_through(more);
  CHECK(file_bytes(out) == file_bytes(straight));
  SECTION("and refuses to take samples away") {
    std::vector<std::string> fewer = path_render(scene(), out, 32);
    fewer.push_back("--resume");
    const CommandResult r = run_clrt(joined(fewer));
    CHECK(r.exit_code == 2);
    CHECK(r.output.find("has 64 samples per pixel already; --spp 32 cannot take them away") !=
          std::string::npos);
    CHECK(file_bytes(out) == file_bytes(straight));
  }
}

TEST_CASE("resuming refuses a state of another scene or other options", "[cli][resume]") {
  ScratchDir dir;
  const std::string copy = dir.file("scene.ray"), out = dir.file("out.png");
  fs::copy_file(scene(), copy);
  std::vector<std::string> words = path_render(copy, out, 16);
  words.push_back("--resume");
  render_through(words);
  std::string before = file_bytes(out);
  const auto refused = [&](std::vector<std::string> changed, const std::string& message) {
    const CommandResult r = run_clrt(joined(changed));
    INFO(r.output);
    CHECK(r.exit_code == 2);
    CHECK(r.output.find("clrt: error: --resume: " + out + ".clrt-resume " + message) !=
          std::string::npos);
    CHECK(file_bytes(out) == before);
  };
  SECTION("another seed") {
    words.insert(words.end(), {"--seed", "5"});
    refused(words, "was rendered with seed=0, not seed=5");
  }
  SECTION("another depth") {
    words.insert(words.end(), {"--max-depth", "3"});  // the scene's is 2
    refused(words, "was rendered with max-depth=2, not max-depth=3");
  }
  SECTION("another size") {
    words[4] = "32x16";
    refused(words, "was rendered with resolution=32x32 region=0,0,32x32, not resolution=32x16 "
                   "region=0,0,32x16");
  }
  SECTION("a changed scene") {
    std::ofstream(copy, std::ios::app) << "\n# one more line\n";
    refused(words, "was rendered from other scene files");
  }
  SECTION("trace mode's samples cannot grow") {
    fs::remove(out + ".clrt-resume");
    std::vector<std::string> trace = words;
    trace[2] = "trace";
    render_through(trace);
    before = file_bytes(out);
    trace[6] = "32";
    refused(trace, "was rendered with spp=16, not spp=32 (outside path mode the samples per pixel "
                   "cannot grow");
  }
  SECTION("an output with no file to keep a state beside") {
    const CommandResult r = run_clrt(joined({copy, "-o", "-", "--format", "png", "--resume"}));
    CHECK(r.exit_code == 2);
    CHECK(r.output.find("--resume needs an image file to keep a state beside: standard output") !=
          std::string::npos);
  }
}

TEST_CASE("a stopped animation resumes at its first unfinished frame", "[cli][resume]") {
  ScratchDir dir, logs;
  const auto frames = [&](const std::string& name) {
    std::vector<std::string> words = path_render(scene(), dir.file(name), 16);
    words.insert(words.end(), {"--frames", "3"});
    return words;
  };
  render_through(frames("straight.png"));
  // 4 rounds a frame: round 6 is frame 2's second.
  REQUIRE(WIFSIGNALED(stopped_render(frames("out.png"), 6, SIGINT, dir.file("hold"),
                                     logs.file("log"), dir.path().string())));
  CHECK(dir.entries() == std::set<std::string>{"hold", "out-0001.png", "out-0002.png",
                                               "out.png.clrt-resume", "straight-0001.png",
                                               "straight-0002.png", "straight-0003.png"});
  CHECK(file_bytes(dir.file("out-0001.png")) == file_bytes(dir.file("straight-0001.png")));
  CHECK(file_bytes(dir.file("out-0002.png")).find("8/16") != std::string::npos);
  std::vector<std::string> resume = frames("out.png");
  resume.push_back("--resume");
  const CommandResult r = run_clrt(joined(resume));
  INFO(r.output);
  REQUIRE(r.exit_code == 0);
  CHECK(r.output.find("resuming " + dir.file("out.png") + " at frame 2 from 8/16 spp") !=
        std::string::npos);
  CHECK(r.output.find("wrote " + dir.file("out-0001.png")) == std::string::npos);  // done before
  for (const char* n : {"-0001.png", "-0002.png", "-0003.png"})
    CHECK(file_bytes(dir.file(std::string("out") + n)) ==
          file_bytes(dir.file(std::string("straight") + n)));
  CHECK_FALSE(fs::exists(dir.file("out.png.clrt-resume")));  // a finished animation keeps none
}

// The command line behaves like the tools users know: --stats is a flag in any position, every
// error starts "clrt: error:" and usage errors exit 2, an unknown option or command is named
// with the nearest real name, a count that is no number says so, pbrt's spellings work,
// outputs that cannot be written are refused before any work, --threads changes nothing but
// the speed, every tool has --version and exits 2 on a usage error, and the progress line fits
// the terminal and names its phases.
#include <catch2/catch.hpp>

#include <regex>
#include <sstream>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

#include "render_support.hpp"
#include "scratch_dir.hpp"

using namespace clrt;
using namespace clrt::test;

namespace {

std::string scene_args(const ScratchDir& dir) {
  return quoted(test_scene("test2.ray")) + " --resolution 20x12 -o " + dir.file("out.pfm");
}

// Each pair's arguments, given with a scene, end with exit 2 and a message that starts as given.
void check_usage_errors(const ScratchDir& dir,
                        const std::vector<std::pair<std::string, std::string>>& cases) {
  for (const auto& [args, message] : cases) {
    const CommandResult r = run_clrt(args + " " + scene_args(dir));
    INFO(args << ": " << r.output);
    CHECK(r.exit_code == 2);
    CHECK(r.output.rfind(message, 0) == 0);
  }
}

}  // namespace

TEST_CASE("the stats option is a flag in any position, and its JSON form too", "[cli][usage]") {
  ScratchDir dir;
  const std::string out = " -o " + dir.file("out.png") + " --resolution 20x12 -q ";
  const std::string scene = quoted(test_scene("test2.ray"));
  for (const std::string& args : {"--stats " + scene + out, scene + " --stats" + out,
                                  out + scene + " --stats"}) {
    const CommandResult r = run_clrt(args);
    INFO(args << ": " << r.output);
    CHECK(r.exit_code == 0);
    CHECK(r.output.find("rays:") != std::string::npos);
  }
  const CommandResult json = run_clrt("--stats=json " + scene + out);
  CHECK(json.exit_code == 0);
  CHECK(json.output.find("\"rays\": {") != std::string::npos);
}

TEST_CASE("usage errors exit 2 and start 'clrt: error:'", "[cli][usage]") {
  ScratchDir dir;
  for (const std::string& args :
       {std::string("--no-such-option ") + scene_args(dir), std::string("--spp 0 ") + scene_args(dir),
        std::string("--resolution 10 ") + scene_args(dir), std::string("-q"),
        std::string("--stats=xml ") + scene_args(dir), std::string("--threads 0 ") + scene_args(dir),
        scene_args(dir) + " --integrator pathtracer"}) {
    const CommandResult r = run_clrt(args);
    INFO(args << ": " << r.output);
    CHECK(r.exit_code == 2);
    CHECK(r.output.rfind("clrt: error:", 0) == 0);
  }
}

TEST_CASE("an unknown option is named, with the nearest real one when one is close",
          "[cli][usage]") {
  const std::string scene = quoted(test_scene("test2.ray"));
  const std::string resolution =
      "clrt: error: unknown option --resolutoin (did you mean --resolution?)\n";
  for (const auto& [args, message] : std::vector<std::pair<std::string, std::string>>{
           {"--resolutoin 100x100 " + scene, resolution},
           {scene + " --resolutoin=100x100", resolution},
           {"--sp 2 " + scene, "clrt: error: unknown option --sp (did you mean --spp?)\n"},
           {"--nthread 2 " + scene,
            "clrt: error: unknown option --nthread (did you mean --nthreads?)\n"},
           {"-x " + scene, "clrt: error: unknown option -x\n"},
           {"--frobnicate " + scene, "clrt: error: unknown option --frobnicate\n"}}) {
    const CommandResult r = run_clrt(args);
    INFO(args << ": " << r.output);
    CHECK(r.exit_code == 2);
    CHECK(r.output.rfind(message, 0) == 0);
  }
}

TEST_CASE("a second scene is named, with the one already given", "[cli][usage]") {
  const std::string first = test_scene("test2.ray"), second = test_scene("reflect.ray");
  const CommandResult r = run_clrt(quoted(first) + " " + quoted(second) + " -o none");
  INFO(r.output);
  CHECK(r.exit_code == 2);
  CHECK(r.output.rfind("clrt: error: unexpected argument '" + second +
                           "' (clrt takes one scene, already given as '" + first + "')\n",
                       0) == 0);
  const CommandResult two = run_clrt(quoted(first) + " a.ray b.ray -o none");
  CHECK(two.exit_code == 2);
  CHECK(two.output.rfind("clrt: error: unexpected arguments 'a.ray' 'b.ray'", 0) == 0);
}

TEST_CASE("a number that is no number says so, one out of range names the range",
          "[cli][usage]") {
  ScratchDir dir;
  check_usage_errors(dir, {
           {"--spp abc", "clrt: error: --spp: abc is not a whole number\n"},
           {"--spp 2.5", "clrt: error: --spp: 2.5 is not a whole number\n"},
           {"--spp 0", "clrt: error: --spp: 0 is not in the range 1 to 65536\n"},
           {"--seed x1", "clrt: error: --seed: x1 is not a seed: seeds are the whole numbers 0 to "
                         "4294967295\n"},
           {"--seed -1", "clrt: error: --seed: -1 is not a seed: seeds are the whole numbers 0 to "
                         "4294967295\n"},
           {"--orbit abc", "clrt: error: --orbit: abc is not a number\n"},
           {"--orbit 1e999", "clrt: error: --orbit: 1e999 is not a number\n"},
           {"--orbit nan", "clrt: error: --orbit: nan is not a number\n"},
           {"--frames -3", "clrt: error: --frames: -3 is not in the range 1 to 16777216\n"}});
  // Decimal, whatever the leading zeros (CLI11 alone would read 010 as octal 8).
  const CommandResult ten = run_clrt("--spp 010 --stats -q " + scene_args(dir));
  CHECK(ten.exit_code == 0);
  CHECK(ten.output.find("(20x12, 10 samples per pixel)") != std::string::npos);
}

TEST_CASE("a word an option does not take names the words it does, and the nearest",
          "[cli][usage]") {
  ScratchDir dir;
  check_usage_errors(dir, {
           {"--mode paht", "clrt: error: --mode: paht is not one of trace, cast, path (did you mean path?)\n"},
           {"--mode xyz", "clrt: error: --mode: xyz is not one of trace, cast, path\n"},
           {"--integrator megakernal",
            "clrt: error: --integrator: megakernal is not one of wavefront, megakernel (did you mean "
            "megakernel?)\n"},
           {"--exr-pixel flaot", "clrt: error: --exr-pixel: flaot is not one of half, float (did you mean float?)\n"},
           {"--shade-order clas", "clrt: error: --shade-order: clas is not one of queue, class (did you mean class?)\n"},
           {"--stats-format jsn", "clrt: error: --stats-format: jsn is not one of text, json (did you mean json?)\n"}});
  // Any case, as before.
  CHECK(run_clrt("--mode PATH --spp 1 -q " + scene_args(dir)).exit_code == 0);
}

TEST_CASE("every tool words a bad number as clrt does", "[cli][usage]") {
  for (const auto& [tool, args, message] : std::vector<std::tuple<std::string, std::string, std::string>>{
           {CLRT_IMG_EXE, "diff a.png b.png --threshold x",
            "clrt-img: error: --threshold: x is not a number\n"},
           {CLRT_IMG_EXE, "diff a.png b.png --threshold -1",
            "clrt-img: error: --threshold: -1 is less than 0\n"},
           {CLRT_IMG_EXE, "convert a.ppm a.gif --fps 0",
            "clrt-img: error: --fps: 0 is not in the range 0.1 to 100\n"},
           {CLRT_MAKE_SCENES_EXE, "--scale 0", "clrt-make-scenes: error: --scale: 0 is not above 0\n"},
           {CLRT_EXPERIMENT_EXE, "--spp abc s.ray",
            "clrt-experiment: error: --spp: abc is not a whole number\n"},
           {CLRT_BENCH_EXE, "bvh --runs 1.5", "clrt-bench: error: --runs: 1.5 is not a whole number\n"}}) {
    const CommandResult r = run_program(tool, args);
    INFO(tool << " " << args << ": " << r.output);
    CHECK(r.exit_code == 2);
    CHECK(r.output.rfind(message, 0) == 0);
  }
}

TEST_CASE("a scene that is missing or no text is named without a line, and an empty one is rendered "
          "with a warning",
          "[cli][usage]") {
  ScratchDir dir;
  const std::string out = " -o " + dir.file("out.png");
  const CommandResult missing = run_clrt(quoted(dir.file("nosuch.ray")) + out);
  CHECK(missing.exit_code == 2);
  CHECK(missing.output == dir.file("nosuch.ray") +
                              ": error: cannot read the scene file (No such file or directory)\n");
  REQUIRE(run_clrt(quoted(test_scene("test2.ray")) + " -q --resolution 8x8 -o " + dir.file("r.png"))
              .exit_code == 0);
  const CommandResult png = run_clrt(quoted(dir.file("r.png")) + out);
  CHECK(png.exit_code == 2);
  CHECK(png.output == dir.file("r.png") + ": error: this is a PNG image, not a scene\n");
  const std::string empty = dir.write("empty.ray", "# nothing yet\nbackground 0.2 0.2 0.2\n");
  const CommandResult warned = run_clrt(quoted(empty) + " --resolution 8x8" + out);
  INFO(warned.output);
  CHECK(warned.exit_code == 0);
  CHECK(warned.output.find("clrt: warning: " + empty + " has no objects: the image is its background\n") !=
        std::string::npos);
  CHECK(run_clrt(quoted(empty) + " -q --resolution 8x8" + out).output.empty());
}

TEST_CASE("pbrt's spellings --outfile, --nthreads, --pixelbounds and --cropwindow work",
          "[cli][usage]") {
  ScratchDir dir;
  const std::string scene = quoted(test_scene("reflect.ray")) + " -q --resolution 20x12 ";
  const std::string bounds = dir.file("bounds.pfm");
  REQUIRE(run_clrt(scene + "--pixel-bounds 6,15,2,11 -o " + bounds).exit_code == 0);
  // pbrt's crop window: pixels ceil(20 x 0.26) = 6 to ceil(20 x 0.74) = 15, ceil(12 x 0.1) = 2
  // to ceil(12 x 0.9) = 11.
  for (const std::string& args :
       {std::string("--pixelbounds 6 15 2 11 --nthreads 1"),
        std::string("--pixelbounds=6,15,2,11"), std::string("--cropwindow 0.26 0.74 0.1 0.9"),
        std::string("--cropwindow 0.26,0.74,0.1,0.9 --nthreads 2")}) {
    INFO(args);
    const std::string out = dir.file("alias.pfm");
    REQUIRE(run_clrt(scene + args + " --outfile " + out).exit_code == 0);
    CHECK(file_bytes(out) == file_bytes(bounds));
  }
}

TEST_CASE("the help lists the options in groups and ends pointing to the man page and docs/cli.md",
          "[cli][usage]") {
  const CommandResult help = run_clrt("--help");
  CHECK(help.exit_code == 0);
  std::size_t at = 0;
  for (const char* group : {"\nScene and image:\n", "\nRendering:\n", "\nDevices:\n",
                            "\nOutput:\n", "\nAnimation:\n", "\nDiagnostics:\n"}) {
    INFO(group << help.output);
    at = help.output.find(group, at);
    CHECK(at != std::string::npos);
  }
  CHECK(help.output.find("--spp INT:1 to 65536") != std::string::npos);
  // Run from the build tree: the source tree's page.
  CHECK(help.output.find("man clrt, and " + std::string(CLRT_SOURCE_DIR) + "/docs/cli.md") != std::string::npos);
  const std::string last = "/docs/cli.md\n";
  CHECK(help.output.size() > last.size());
  CHECK(help.output.compare(help.output.size() - last.size(), last.size(), last) == 0);
}

TEST_CASE("an output that is a folder or in no folder is refused before any work",
          "[cli][usage]") {
  ScratchDir dir;
  const std::string scene = quoted(test_scene("test2.ray")) + " --resolution 20x12 -o ";
  const CommandResult folder = run_clrt(scene + dir.path().string());
  INFO(folder.output);
  CHECK(folder.exit_code == 2);
  CHECK(folder.output.find("it is a folder") != std::string::npos);
  // Before any work: not even the device was chosen.
  CHECK(folder.output.find("device ") == std::string::npos);
  const CommandResult missing = run_clrt(scene + dir.file("no/such/folder/out.png"));
  CHECK(missing.exit_code == 2);
  CHECK(missing.output.find("folder: No such file or directory") != std::string::npos);
}

TEST_CASE("a thread count changes nothing but the speed", "[cli][usage]") {
  ScratchDir dir;
  const std::string scene = quoted(test_scene("reflect.ray")) + " -q --resolution 40x24 --spp 2 ";
  REQUIRE(run_clrt(scene + "-o " + dir.file("all.pfm")).exit_code == 0);
  REQUIRE(run_clrt(scene + "--threads 1 -o " + dir.file("one.pfm")).exit_code == 0);
  CHECK(file_bytes(dir.file("all.pfm")) == file_bytes(dir.file("one.pfm")));
}

TEST_CASE("every tool names its version and exits 2 on a usage error", "[cli][usage]") {
  for (const std::string& tool : {std::string(CLRT_EXE), std::string(CLRT_IMG_EXE),
                                  std::string(CLRT_EXPERIMENT_EXE), std::string(CLRT_MAKE_SCENES_EXE),
                                  std::string(CLRT_BENCH_EXE)}) {
    INFO(tool);
    const CommandResult version = run_program(tool, "--version");
    CHECK(version.exit_code == 0);
    CHECK(version.output.find("clrt 0.1.0 (commit ") != std::string::npos);
    const CommandResult bad = run_program(tool, "--no-such-option");
    CHECK(bad.exit_code == 2);
    CHECK(bad.output.find(": error: unknown option --no-such-option\n") != std::string::npos);
    const CommandResult typo = run_program(tool, "--versoin");
    CHECK(typo.exit_code == 2);
    CHECK(typo.output.find(": error: unknown option --versoin (did you mean --version?)\n") !=
          std::string::npos);
  }
}

TEST_CASE("clrt-img names an unknown command and the nearest real one", "[cli][usage]") {
  const CommandResult typo = run_program(CLRT_IMG_EXE, "conver a.fsf b.png");
  CHECK(typo.exit_code == 2);
  CHECK(typo.output.rfind("clrt-img: error: unknown command conver (did you mean convert?)\n",
                          0) == 0);
  const CommandResult none = run_program(CLRT_IMG_EXE, "");
  CHECK(none.exit_code == 2);
  CHECK(none.output.rfind("clrt-img: error: a command is required: convert, info, diff, stitch\n",
                          0) == 0);
  const CommandResult option = run_program(CLRT_IMG_EXE, "diff a.png b.png --treshold 2");
  CHECK(option.exit_code == 2);
  CHECK(option.output.rfind(
            "clrt-img: error: unknown option --treshold (did you mean --threshold?)\n", 0) == 0);
  // The options of another command are unknown to this one.
  const CommandResult other = run_program(CLRT_IMG_EXE, "convert a.png b.png --threshold 2");
  CHECK(other.exit_code == 2);
  CHECK(other.output.rfind("clrt-img: error: unknown option --threshold\n", 0) == 0);
}

TEST_CASE("on a terminal the progress line names its phases, fits the width and ends with the file",
          "[cli][usage]") {
  ScratchDir dir;
  // script(1) gives clrt a terminal of 50 columns; its output is what the terminal received.
  const std::string command = "stty cols 50; '" + std::string(CLRT_EXE) + "' " +
                              quoted(test_scene("reflect.ray")) + " --resolution 200x120 -o " +
                              dir.file("out.png");
  const CommandResult r = run_program("script", "-qec " + quoted(command) + " /dev/null");
  INFO(r.output);
  REQUIRE(r.exit_code == 0);
  CHECK(r.output.find("loading ") != std::string::npos);
  CHECK(r.output.find("rendering") != std::string::npos);
  CHECK(r.output.find("wrote " + dir.file("out.png")) != std::string::npos);
  // Every redraw ("\r\033[K" then the line) fits in 49 columns. The terminal turned each
  // newline into "\r\n": turn it back.
  std::string text = r.output;
  for (std::size_t at; (at = text.find("\r\n")) != std::string::npos;) text.erase(at, 1);
  std::istringstream redraws(text);
  std::string piece;
  // Messages (the device line, the last line) end with a newline and are not redraws.
  int redrawn = 0;
  while (std::getline(redraws, piece, '\r')) {
    if (piece.rfind("\033[K", 0) != 0 || piece.find('\n') != std::string::npos) continue;
    INFO(piece);
    CHECK(piece.size() - 3 <= 49);
    ++redrawn;
  }
  CHECK(redrawn >= 3);
}

TEST_CASE("the kernel build is named as a phase when the program cache does not hold it",
          "[cli][usage]") {
  ScratchDir dir;
  const std::string command = "stty cols 80; CLRT_CACHE_DIR=" + dir.file("cache") + " '" +
                              std::string(CLRT_EXE) + "' " + quoted(test_scene("test2.ray")) +
                              " --resolution 20x12 -o " + dir.file("out.png");
  const auto run = [&] { return run_program("script", "-qec " + quoted(command) + " /dev/null"); };
  const CommandResult cold = run();
  INFO(cold.output);
  REQUIRE(cold.exit_code == 0);
  CHECK(cold.output.find("building kernels (first run on this device)") != std::string::npos);
  const CommandResult warm = run();
  REQUIRE(warm.exit_code == 0);
  CHECK(warm.output.find("building kernels") == std::string::npos);
}

TEST_CASE("without clrt's program cache the kernel build is named without claiming a first run",
          "[cli][usage]") {
  ScratchDir dir;
  const std::string command = "stty cols 80; CLRT_CACHE_DIR= '" + std::string(CLRT_EXE) + "' " +
                              quoted(test_scene("test2.ray")) + " --resolution 20x12 -o " + dir.file("out.png");
  const CommandResult r = run_program("script", "-qec " + quoted(command) + " /dev/null");
  INFO(r.output);
  REQUIRE(r.exit_code == 0);
  CHECK(r.output.find("building kernels") != std::string::npos);
  CHECK(r.output.find("first run") == std::string::npos);
}

TEST_CASE("redirected, clrt prints its device in 80 columns and a line per image written",
          "[cli][usage]") {
  ScratchDir dir;
  const std::string scene = quoted(test_scene("test2.ray")) + " --resolution 20x12 -o ";
  const CommandResult still = run_clrt(scene + dir.file("out.png"));
  INFO(still.output);
  REQUIRE(still.exit_code == 0);
  const std::string device_line = still.output.substr(0, still.output.find('\n'));
  CHECK(device_line.rfind("device 0:", 0) == 0);
  CHECK(device_line.size() <= 80);
  CHECK(std::regex_search(still.output, std::regex("\nclrt: wrote " + dir.file("out.png") +
                                                   " \\(20x12, [0-9.]+ s\\)\n$")));
  const CommandResult turn = run_clrt(scene + dir.file("turn.png") + " --frames 2");
  INFO(turn.output);
  REQUIRE(turn.exit_code == 0);
  CHECK(turn.output.find("clrt: wrote " + dir.file("turn-0001.png") + " (20x12, ") != std::string::npos);
  CHECK(turn.output.find("clrt: wrote " + dir.file("turn-0002.png") + " (20x12, ") != std::string::npos);
  CHECK(turn.output.find("clrt: wrote 2 frames as ") != std::string::npos);
}

TEST_CASE("clrt-bench load times each scene once in a fresh process beside the best of its runs",
          "[cli][usage]") {
  const std::string mesh = std::string(CLRT_SOURCE_DIR) + "/scenes/mesh.ray", spheres = test_scene("reflect.ray");
  const CommandResult r = run_program(CLRT_BENCH_EXE, "load " + quoted(mesh) + " " + quoted(spheres) + " --runs 2");
  REQUIRE(r.exit_code == 0);
  CHECK(r.output.find("| load + build Mtris/s | fresh process: load + build ms |\n") != std::string::npos);
  // A row per scene, in their order: the path, its triangles, six figures of the best runs and
  // the fresh run's load and build.
  const std::regex row(R"(\| ([^|]+) \| (\d+) \|( [0-9.]+ \|){6} ([0-9.]+) \+ ([0-9.]+) \|\n)");
  std::vector<std::smatch> rows;
  for (auto it = std::sregex_iterator(r.output.begin(), r.output.end(), row); it != std::sregex_iterator(); ++it)
    rows.push_back(*it);
  REQUIRE(rows.size() == 2);
  CHECK(rows[0][1].str() == mesh);
  CHECK(std::stoul(rows[0][2].str()) > 0);
  CHECK(rows[1][1].str() == spheres);
  CHECK(rows[1][2].str() == "0");
  for (const std::smatch& m : rows) CHECK(std::stod(m[4].str()) > 0);

  // A scene that fails fails in the fresh process first, with its own message.
  const CommandResult missing = run_program(CLRT_BENCH_EXE, "load /nonexistent/none.ray --runs 1");
  CHECK(missing.exit_code == 1);
  CHECK(missing.output.find("/nonexistent/none.ray: error: cannot read the scene file") != std::string::npos);
  CHECK(missing.output.find("clrt-bench: error: the fresh run of /nonexistent/none.ray failed\n") != std::string::npos);
}

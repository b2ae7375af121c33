// clrt-experiment end to end on tiny scenes: two PoCL devices x two integrators x repeats in one
// command, with every output (JSON, CSV, Markdown, plots) and the validation of every image;
// a variant that changes the picture is flagged with its PSNR; a wavefront sweep draws its plot.
#include <catch2/catch.hpp>

#include <fcntl.h>
#include <signal.h>
#include <spawn.h>
#include <sys/stat.h>
#include <sys/wait.h>

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <nlohmann/json.hpp>
#include <regex>
#include <string>
#include <thread>

#include "image/image.hpp"
#include "process_run.hpp"
#include "rank_test.hpp"
#include "report.hpp"
#include "scratch_dir.hpp"

using namespace clrt;
using namespace clrt::experiment;

extern char** environ;

namespace {

const std::string kTwoDevices = "POCL_DEVICES=pthread pthread";

std::string source_file(const std::string& relative) {
  return std::string(CLRT_SOURCE_DIR) + "/" + relative;
}

ProcessResult run_experiment(std::vector<std::string> args, const std::vector<std::string>& env = {}) {
  args.insert(args.begin(), CLRT_EXPERIMENT);
  return run_process(args, env);
}

std::string text_of(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

nlohmann::json results_in(const test::ScratchDir& dir) {
  return nlohmann::json::parse(text_of(dir.file("results.json")));
}

void check_plot(const std::string& path) {
  INFO(path);
  const Rgba8Image plot = read_png(path);
  CHECK(plot.width > 100);
  CHECK(plot.height > 100);
}

}  // namespace

TEST_CASE("two devices, two integrators and repeats in one command, every image validated",
          "[experiment]") {
  test::ScratchDir dir;
  const ProcessResult r =
      run_experiment({source_file("tests/render/scenes/test2.ray"), "--device", "all", "--integrator",
                  "wavefront,megakernel", "--repeats", "2", "--resolution", "32x24", "--out",
                  dir.path().string()},
                 {kTwoDevices});
  INFO(r.out << r.err);
  REQUIRE(r.exit_code == 0);
  const nlohmann::json results = results_in(dir);
  CHECK(results["clrt"].get<std::string>().find("clrt ") == 0);
  const nlohmann::json& runs = results["runs"];
  REQUIRE(runs.size() == 8);  // 1 scene x 2 devices x 2 integrators x 2 repeats
  // One warm-up of each configuration first, kept apart.
  REQUIRE(results["warmup_runs"].size() == 4);
  for (const nlohmann::json& w : results["warmup_runs"]) {
    CHECK(w["warmup"] == true);
    CHECK(w["exit_code"] == 0);
  }
  for (const nlohmann::json& run : runs) {
    CHECK(run["exit_code"] == 0);
    CHECK(run["rays"]["camera"] == 32 * 24);
    CHECK(run["rays"]["total"].get<int>() > 32 * 24);
    CHECK(run["mrays_per_second"].get<double>() > 0);
    CHECK(run["peak_bytes"].get<double>() > 0);
    CHECK(run["process_seconds"].get<double>() >= run["seconds"]["total"].get<double>());
    CHECK(run["devices"][0]["name"].get<std::string>().size() > 0);
    CHECK(run["devices"][0]["driver"].get<std::string>().size() > 0);
    CHECK(run["devices"][0]["opencl_c"].get<std::string>().find("OpenCL C") == 0);
    CHECK(run["kernels"].size() > 0);
    CHECK(run["validation"]["identical"] == true);
    CHECK(run["validation"]["flagged"] == false);
  }
  CHECK(runs[0]["device_spec"] == "0:0");
  CHECK(runs[2]["device_spec"] == "0:1");
  CHECK(runs[1]["integrator"] == "megakernel");
  CHECK(results["summary"].size() == 4);
  REQUIRE(results["scores"].size() == 2);
  for (const auto& [device, score] : results["scores"].items()) {
    CHECK(score["score"].get<double>() > 0);
    // With the same mean of the slowest and of the fastest repeats around it.
    CHECK(score["spread"][0].get<double>() <= score["score"].get<double>());
    CHECK(score["score"].get<double>() <= score["spread"][1].get<double>());
  }

  const std::string csv = text_of(dir.file("runs.csv"));
  CHECK(std::count(csv.begin(), csv.end(), '\n') == 9);
  CHECK(csv.rfind("scene,device_spec,device,variant,repeat,", 0) == 0);
  const std::string report = text_of(dir.file("report.md"));
  CHECK(report.find("| scene | device | variant | Mrays/s") != std::string::npos);
  CHECK(report.find("megakernel") != std::string::npos);
  CHECK(report.find("Every image is identical to its scene's first.") != std::string::npos);
  CHECK(report.find("\nWarm-up runs, not counted above") != std::string::npos);
  // The megakernel against the wavefront on each device, with 2 repeats too few to tell.
  REQUIRE(results["comparisons"].size() == 2);
  CHECK(results["comparisons"][0]["variant"] == "megakernel");
  CHECK(results["comparisons"][0]["baseline"] == "wavefront");
  CHECK(results["comparisons"][0]["ratio"].get<double>() > 0);
  CHECK(results["comparisons"][0]["smallest_p"].get<double>() == Approx(1.0 / 3));
  CHECK(report.find("Mann-Whitney U test") != std::string::npos);
  CHECK(report.find("--repeats 4 or more can.") != std::string::npos);
  CHECK(report.find("\nDevice seconds per kernel (medians;") != std::string::npos);
  CHECK(report.find(" generate s |") != std::string::npos);
  // 32x24 renders are short: said on the terminal, counted and listed in the report.
  CHECK(r.err.find(", a short render (") != std::string::npos);
  CHECK(results["summary"][0]["short"].get<int>() > 0);
  CHECK(report.find("\nShort renders (under 0.2 s, or under 50% of their command)") !=
        std::string::npos);
  // The machine as the record keeps it.
  const nlohmann::json& machine = results["machine"];
  CHECK_FALSE(machine["cpu_model"].get<std::string>().empty());
  CHECK_FALSE(machine["load_average_before"].get<std::string>().empty());
  CHECK_FALSE(machine["load_average_after"].get<std::string>().empty());
  CHECK(machine["opencl_environment"]["POCL_DEVICES"] == "pthread pthread");
  REQUIRE(machine["devices"].size() == 2);
  CHECK_FALSE(machine["devices"][0]["driver"].get<std::string>().empty());
  CHECK(machine["devices"][0]["platform"] == "Portable Computing Language");
  // The title names what was measured; each table's medians come with the repeats' spread.
  const std::string title = results["title"];
  CHECK(title.rfind("32x24, each scene's samples per pixel, on 0:0 ", 0) == 0);
  CHECK(title.find(", 0:1 ") != std::string::npos);
  CHECK(report.rfind("# " + title + "\n", 0) == 0);
  for (const nlohmann::json& s : results["summary"]) {
    const std::vector<double> range = s["spread"]["mrays_per_second"];
    CHECK(range[0] <= s["mrays_per_second"].get<double>());
    CHECK(s["mrays_per_second"].get<double>() <= range[1]);
    CHECK(s["kernel_spread"].size() == s["kernels"].size());
  }
  CHECK(std::regex_search(report, std::regex(R"(\| [0-9.]+ \([0-9.]+-[0-9.]+\) \| [0-9.]+ \()")));
  CHECK(std::regex_search(report, std::regex(R"(\| [0-9.]+ \([0-9.]+-[0-9.]+\) \|\n)")));  // kernels
  check_plot(dir.file("mrays.png"));
  check_plot(dir.file("kernels.png"));
  CHECK_FALSE(std::filesystem::exists(dir.file("wavefront.png")));
}

TEST_CASE("the Mann-Whitney test against its exact values", "[experiment][statistics]") {
  // Three against three, wholly apart: 2 of the C(6, 3) = 20 splits are as far (either way).
  CHECK(mann_whitney_p({1, 2, 3}, {4, 5, 6}) == Approx(0.1));
  CHECK(mann_whitney_p({4, 5, 6}, {1, 2, 3}) == Approx(0.1));
  CHECK(smallest_mann_whitney_p(3, 3) == Approx(0.1));
  CHECK(mann_whitney_p({1, 2, 3, 4}, {5, 6, 7, 8}) == Approx(2.0 / 70));
  CHECK(smallest_mann_whitney_p(4, 4) == Approx(2.0 / 70));
  // Interleaved or equal: nothing to tell apart.
  CHECK(mann_whitney_p({1, 3, 5}, {2, 4, 6}) == Approx(0.7));
  CHECK(mann_whitney_p({1, 1, 1}, {1, 1, 1}) == Approx(1));
  CHECK(mann_whitney_p({}, {1, 2}) == 1);
  // Beyond 20 values, the normal approximation: 15 against 15 wholly apart.
  std::vector<double> low, high;
  for (int i = 0; i < 15; ++i) {
    low.push_back(i);
    high.push_back(100 + i);
  }
  CHECK(mann_whitney_p(low, high) < 1e-5);
}

TEST_CASE("a run whose picture differs is flagged with its PSNR and kept", "[experiment]") {
  test::ScratchDir dir;
  const ProcessResult r = run_experiment(
      {source_file("tests/render/scenes/area.ray"), "--repeats", "1", "--resolution", "24x16",
       "--variant", "seed0=", "--variant", "seed9=--seed 9", "--out", dir.path().string(), "--no-plots"});
  INFO(r.out << r.err);
  CHECK(r.exit_code == 1);
  CHECK(r.err.find("1 images differ") != std::string::npos);
  const nlohmann::json runs = results_in(dir)["runs"];
  REQUIRE(runs.size() == 2);
  CHECK(runs[0]["validation"]["flagged"] == false);
  const nlohmann::json& v = runs[1]["validation"];
  CHECK(v["flagged"] == true);
  CHECK(v["identical"] == false);
  CHECK(v["differing_pixels"].get<int>() > 0);
  CHECK(v["psnr"].get<double>() > 0);
  CHECK(std::filesystem::exists(runs[1]["command"][7].get<std::string>()));
  CHECK(text_of(dir.file("report.md")).find("differs from the scene's first image: area.ray") !=
        std::string::npos);
}

TEST_CASE("an experiment stopped part-way keeps its finished runs, and --resume runs the rest",
          "[experiment][resume]") {
  test::ScratchDir dir;
  std::vector<std::string> args = {CLRT_EXPERIMENT, source_file("tests/render/scenes/area.ray"),
                                   "--repeats", "30", "--resolution", "8x8",
                                   "--out", dir.path().string(), "--no-plots"};
  std::vector<char*> argv;
  for (std::string& arg : args) argv.push_back(arg.data());
  argv.push_back(nullptr);
  const std::string err = dir.file("stderr.txt");
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, STDERR_FILENO, err.c_str(),
                                   O_WRONLY | O_CREAT | O_TRUNC, 0644);
  pid_t pid = -1;
  REQUIRE(posix_spawn(&pid, CLRT_EXPERIMENT, &actions, nullptr, argv.data(), environ) == 0);
  posix_spawn_file_actions_destroy(&actions);
  // Interrupted (as Ctrl-C does) once its first run is written down.
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(120);
  while (!std::filesystem::exists(dir.file("results.json")) &&
         std::chrono::steady_clock::now() < deadline)
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  kill(pid, SIGINT);
  int status = 0;
  waitpid(pid, &status, 0);
  const nlohmann::json part = results_in(dir);
  REQUIRE(part["complete"] == false);
  const std::size_t kept = part["runs"].size();
  CHECK(kept >= 1);
  CHECK(kept < 30);
  // It says what it kept and how to go on, and exits as a program stopped by Ctrl-C does.
  CHECK(WIFEXITED(status));
  CHECK(WEXITSTATUS(status) == 130);
  CHECK(text_of(err).find("\nclrt-experiment: interrupted: " + std::to_string(kept) +
                          " of 30 runs kept in " + dir.file("results.json") +
                          "; the same command with --resume runs the other " +
                          std::to_string(30 - kept) + "\n") != std::string::npos);

  const ProcessResult resumed =
      run_experiment({args[1], "--repeats", "30", "--resolution", "8x8", "--out",
                      dir.path().string(), "--no-plots", "--resume"});
  INFO(resumed.err);
  CHECK(resumed.exit_code == 0);
  const nlohmann::json whole = results_in(dir);
  CHECK(whole["complete"] == true);
  REQUIRE(whole["runs"].size() == 30);
  for (std::size_t i = 0; i < kept; ++i) CHECK(whole["runs"][i] == part["runs"][i]);
  for (const nlohmann::json& run : whole["runs"]) CHECK(run["validation"]["flagged"] == false);
  // Two sessions, each with its date, load and runs, and each run with the session that measured it.
  const nlohmann::json& sessions = whole["sessions"];
  REQUIRE(sessions.size() == 2);
  CHECK(sessions[0] == part["sessions"][0]);
  CHECK(sessions[0]["runs"] == kept);
  CHECK(sessions[1]["runs"] == 30 - kept);
  for (const nlohmann::json& session : sessions) {
    CHECK(session["started"].get<std::string>().size() == 20);
    CHECK(session["ended"].get<std::string>() >= session["started"].get<std::string>());
    CHECK(one_minute_load(session["load_average_before"]) >= 0);
    CHECK(one_minute_load(session["load_average_after"]) >= 0);
  }
  CHECK(whole["runs"][0]["session"] == 1);
  CHECK(whole["runs"][29]["session"] == 2);
  const std::string report = text_of(dir.file("report.md"));
  CHECK(report.find("\n| 1 | " + sessions[0]["started"].get<std::string>() + " | ") !=
        std::string::npos);
  CHECK(report.find("\n| 2 | " + sessions[1]["started"].get<std::string>() + " | ") !=
        std::string::npos);

  // Other settings are another experiment: refused, the results left as they are.
  const ProcessResult other = run_experiment({args[1], "--repeats", "31", "--resolution", "8x8",
                                              "--out", dir.path().string(), "--no-plots",
                                              "--resume"});
  CHECK(other.exit_code == 2);
  CHECK(other.err.find("--resume: ") != std::string::npos);
  CHECK(other.err.find("holds another experiment") != std::string::npos);
  CHECK(results_in(dir) == whole);
}

TEST_CASE("a path-mode experiment traces every run, both integrators to the same image",
          "[experiment][path]") {
  test::ScratchDir dir;
  const ProcessResult r = run_experiment(
      {source_file("tests/render/scenes/area.ray"), "--mode", "path", "--integrator",
       "wavefront,megakernel", "--variant", "queue=", "--variant", "by-class=--shade-order class",
       "--repeats", "1",
       "--resolution", "16x12", "--spp", "2", "--out", dir.path().string(), "--no-plots"});
  INFO(r.out << r.err);
  CHECK(r.exit_code == 0);
  const nlohmann::json results = results_in(dir);
  CHECK(results["settings"]["mode"] == "path");
  REQUIRE(results["runs"].size() == 4);
  for (const nlohmann::json& run : results["runs"]) {
    const std::vector<std::string> command = run["command"];
    CHECK(std::find(command.begin(), command.end(), "path") != command.end());
    CHECK(run["validation"]["flagged"] == false);
  }
}

TEST_CASE("a wavefront sweep draws its plot", "[experiment]") {
  test::ScratchDir dir;
  const ProcessResult r =
      run_experiment({source_file("tests/render/scenes/test2.ray"), "--repeats", "1", "--resolution",
                  "32x24", "--wavefront", "1024,4096", "--out", dir.path().string()});
  INFO(r.out << r.err);
  REQUIRE(r.exit_code == 0);
  const nlohmann::json summary = results_in(dir)["summary"];
  REQUIRE(summary.size() == 2);
  CHECK(summary[0]["wavefront"] == 1024);
  CHECK(summary[1]["wavefront"] == 4096);
  check_plot(dir.file("wavefront.png"));
}

TEST_CASE("a failed run shows clrt's own message on the terminal and in the report",
          "[experiment]") {
  test::ScratchDir dir;
  const std::string bad = dir.write("bad1.ray", "sphere\nfrobnicate\n");
  const ProcessResult r = run_experiment({bad, "--repeats", "1", "--resolution", "8x8", "--out",
                                          dir.path().string(), "--no-plots"});
  INFO(r.out << r.err);
  CHECK(r.exit_code == 1);
  const std::string message = bad + ":2:1: error: unknown command 'frobnicate'";
  CHECK(r.err.find("failed (exit 2): " + message + "\n") != std::string::npos);
  CHECK(text_of(dir.file("report.md")).find("(exit 2): " + message + "\n") != std::string::npos);
}

TEST_CASE("a run clrt refuses shows clrt's error line, not its usage hint", "[experiment]") {
  test::ScratchDir dir;
  const ProcessResult r =
      run_experiment({source_file("tests/render/scenes/test2.ray"), "--repeats", "1",
                      "--resolution", "8x8", "--variant", "frob=--frob", "--out",
                      dir.path().string(), "--no-plots"});
  INFO(r.out << r.err);
  CHECK(r.exit_code == 1);
  const std::string message = "failed (exit 2): clrt: error: unknown option --frob\n";
  CHECK(r.err.find("[warm-up] ") != std::string::npos);
  CHECK(r.err.find("wavefront frob: " + message) != std::string::npos);  // the run that counts
  CHECK(r.err.find("Run 'clrt --help'") == std::string::npos);
  CHECK(text_of(dir.file("report.md")).find("(exit 2): clrt: error: unknown option --frob\n") !=
        std::string::npos);
}

TEST_CASE("a FIFO or folder in the place of an output is refused at once, and left as it is",
          "[experiment][resume]") {
  for (const char* name : {"results.json", "report.md"}) {
    for (const bool resume : {true, false}) {
      test::ScratchDir dir;
      const std::string path = dir.file(name);
      REQUIRE(mkfifo(path.c_str(), 0644) == 0);
      std::vector<std::string> args = {source_file("tests/render/scenes/test2.ray"),
                                       "--repeats", "1", "--resolution", "8x8", "--out",
                                       dir.path().string(), "--no-plots"};
      if (resume) args.push_back("--resume");
      INFO(name << (resume ? " --resume" : ""));
      const ProcessResult r = run_experiment(args);  // blocked on the FIFO, it would never return
      CHECK(r.exit_code == 2);
      CHECK(r.err == "clrt-experiment: error: " + path +
                         " is not a regular file; clrt-experiment writes only regular files "
                         "(remove it, or choose another --out)\n");
      CHECK(std::filesystem::is_fifo(path));
      CHECK_FALSE(std::filesystem::exists(dir.file("images")));
    }
  }
}

namespace {

// A report's results without runs: only the settings and sessions the tests vary.
nlohmann::json results_with(int repeats, const nlohmann::json& sessions) {
  return {{"title", "8x8, 1 spp, on 0:0 PoCL"}, {"clrt", "clrt 0"},
          {"settings", {{"repeats", repeats}}}, {"sessions", sessions},
          {"summary", nlohmann::json::array()}, {"scores", nlohmann::json::object()},
          {"runs", nlohmann::json::array()}, {"comparisons", nlohmann::json::array()},
          {"warmup_runs", nlohmann::json::array()}};
}

nlohmann::json session(const std::string& before, const std::string& after, int threads) {
  return {{"started", "2026-12-07T10:00:00Z"}, {"ended", "2026-12-07T10:05:00Z"},
          {"hardware_threads", threads}, {"load_average_before", before},
          {"load_average_after", after}, {"runs", 4}};
}

}  // namespace

TEST_CASE("the report gives each session's load, and warns of a busy machine",
          "[experiment][report]") {
  const std::string idle = markdown_report(
      results_with(3, nlohmann::json::array(
                         {session("0.40 0.30 0.20 1/300 99", "2.10 1.00 0.50 1/300 99", 2)})));
  CHECK(idle.find("\n| 1 | 2026-12-07T10:00:00Z | 2026-12-07T10:05:00Z | 2 | 0.40 | 2.10 | 4 |\n") !=
        std::string::npos);
  CHECK(idle.find("Warning") == std::string::npos);

  // Other work before the runs (half the threads or more), or more after them than clrt makes.
  const std::string busy = markdown_report(
      results_with(3, nlohmann::json::array(
                         {session("0.40 0.30 0.20 1/300 99", "2.10 1.00 0.50 1/300 99", 2),
                       session("5.65 3.00 2.00 1/300 99", "7.77 4.00 2.00 1/300 99", 2),
                       session("0.50 0.30 0.20 1/300 99", "3.01 1.00 0.50 1/300 99", 2)})));
  CHECK(busy.find("\n| 2 | 2026-12-07T10:00:00Z | 2026-12-07T10:05:00Z | 2 | 5.65 | 7.77 | 4 |\n") !=
        std::string::npos);
  CHECK(busy.find("In session 1 ") == std::string::npos);
  CHECK(busy.find("**Warning: a busy machine.** In session 2 the load average was 5.65 before "
                  "and 7.77 after, on 2 hardware threads") != std::string::npos);
  CHECK(busy.find("In session 3 the load average was 0.50 before and 3.01 after") !=
        std::string::npos);
  CHECK(busy_session(session("0.99", "1.00", 2)) == false);
  CHECK(busy_session(session("1.00", "1.00", 2)) == true);
  CHECK(busy_session(session("0.10", "3.00", 2)) == false);
  CHECK(busy_session(session("0.10", "3.01", 2)) == true);
}

TEST_CASE("a report of one repeat says so", "[experiment][report]") {
  const nlohmann::json sessions = nlohmann::json::array({session("0.1", "0.1", 2)});
  CHECK(markdown_report(results_with(1, sessions)).find("\n\nOne run of each configuration "
                                                        "(--repeats 1: no spread); clrt 0.\n") !=
        std::string::npos);
  CHECK(markdown_report(results_with(1, sessions)).find("over 1 repeat") == std::string::npos);
  CHECK(markdown_report(results_with(2, sessions)).find("\n\nMedians over 2 repeats, their spread "
                                                        "(min-max) in parentheses; clrt 0.\n") !=
        std::string::npos);
}

TEST_CASE("a copied build tree runs its own clrt and plot script", "[experiment]") {
  test::ScratchDir dir;
  const std::filesystem::path built(CLRT_EXPERIMENT), copy = dir.path() / "tree";
  const std::filesystem::path experiment =
      copy / std::filesystem::relative(built, CLRT_BINARY_DIR);
  std::filesystem::create_directories(experiment.parent_path());
  std::filesystem::copy_file(built, experiment);
  std::filesystem::copy_file(built.parent_path() / "plot_experiment.py",
                             experiment.parent_path() / "plot_experiment.py");
  std::filesystem::copy_file(CLRT_EXE, copy / std::filesystem::relative(CLRT_EXE, CLRT_BINARY_DIR));
  const ProcessResult r = run_process({experiment.string(), source_file("tests/render/scenes/test2.ray"),
                                       "--repeats", "1", "--resolution", "8x8", "--out",
                                       (dir.path() / "out").string()});
  INFO(r.out << r.err);
  REQUIRE(r.exit_code == 0);
  const nlohmann::json results = nlohmann::json::parse(text_of((dir.path() / "out/results.json").string()));
  CHECK(results["settings"]["clrt_executable"] == (copy / "clrt").string());
  check_plot((dir.path() / "out/mrays.png").string());
}

TEST_CASE("usage errors exit 2 and a device that matches nothing exits 1", "[experiment]") {
  test::ScratchDir dir;
  CHECK(run_experiment({}).exit_code == 2);
  CHECK(run_experiment({dir.path().string() + "/nothing-here", "--out", dir.path().string()}).exit_code == 2);
  const ProcessResult bad = run_experiment({source_file("tests/render/scenes/test2.ray"),
                                        "--integrator", "pathtracer", "--out", dir.path().string()});
  CHECK(bad.exit_code == 2);
  const ProcessResult device = run_experiment({source_file("tests/render/scenes/test2.ray"),
                                           "--device", "no-such-device", "--out", dir.path().string()});
  CHECK(device.exit_code == 1);
  CHECK(device.err.find("clrt-experiment: error:") == 0);
}

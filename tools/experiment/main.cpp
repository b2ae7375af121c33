// clrt-experiment: throughput experiments across scenes, devices and designs in one command.
// Every run is one clrt process, as a user runs it; runs are interleaved (repeat, scene,
// device, variant) so that a noisy machine spreads its noise over every configuration. Each
// image is compared with its scene's first. Writes results.json, runs.csv, report.md and plots.
#include <CLI/CLI.hpp>

#include <unistd.h>

#include <algorithm>
#include <csignal>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <map>
#include <sstream>
#include <thread>

#include "scene/limits.hpp"
#include "cli/tool_command_line.hpp"
#include "cli/whole_number.hpp"
#include "cli/word_choice.hpp"
#include "device/opencl.hpp"
#include "render/integrator.hpp"
#include "experiment_plan.hpp"
#include "process_run.hpp"
#include "report.hpp"
#include "run_record.hpp"
#include "version.hpp"

extern char** environ;

namespace fs = std::filesystem;
using namespace clrt::experiment;

namespace {

// Set by Ctrl-C (SIGINT). The run under way is let finish, or, when the terminal's Ctrl-C stopped
// clrt with it, left out; then the experiment stops with what it kept written down.
volatile std::sig_atomic_t interrupted = 0;
extern "C" void on_interrupt(int) { interrupted = 1; }

// Thrown between runs once Ctrl-C came: the runs results.json holds, of the plan's `total`.
struct Interrupted {
  std::size_t kept = 0, total = 0;
};

std::string now_text() {
  const std::time_t t = std::time(nullptr);
  char text[32];
  std::strftime(text, sizeof text, "%Y-%m-%dT%H:%M:%SZ", std::gmtime(&t));
  return text;
}

std::string seconds_text(double seconds) {
  std::ostringstream out;
  out << std::fixed << std::setprecision(3) << seconds;
  return out.str();
}

// The first line of `path` that starts with `key`, after its colon ("model name : AMD EPYC"), or
// the file's first line without a key; empty when there is none.
std::string proc_value(const std::string& path, const std::string& key = "") {
  std::ifstream in(path);
  for (std::string line; std::getline(in, line);) {
    if (key.empty()) return line;
    if (line.rfind(key, 0) != 0) continue;
    const std::size_t colon = line.find(':');
    return colon == std::string::npos ? "" : line.substr(line.find_first_not_of(" \t", colon + 1));
  }
  return "";
}

// The variables that change what an OpenCL implementation or clrt does, as they were set.
nlohmann::json opencl_environment() {
  nlohmann::json vars = nlohmann::json::object();
  for (char** e = environ; *e; ++e) {
    const std::string entry = *e;
    const std::string name = entry.substr(0, entry.find('='));
    for (const char* prefix : {"POCL_", "OCL_ICD", "OPENCL_", "DPCPP_", "SYCL_", "CL_", "CLRT_",
                               "OCLGRIND_", "CUDA_VISIBLE_DEVICES"})
      if (name.rfind(prefix, 0) == 0) vars[name] = entry.substr(entry.find('=') + 1);
  }
  return vars;
}

// The machine an experiment ran on: enough to tell two records apart and to judge their noise.
nlohmann::json machine(const Plan& plan) {
  char host[256] = {};
  gethostname(host, sizeof host - 1);
  nlohmann::json devices = nlohmann::json::array();
  for (const DeviceChoice& d : plan.devices)
    devices.push_back({{"spec", d.spec}, {"name", d.name}, {"platform", d.platform},
                       {"driver", d.driver}});
  return {{"hostname", host},
          {"cpu_model", proc_value("/proc/cpuinfo", "model name")},
          {"hardware_threads", std::thread::hardware_concurrency()},
          {"load_average_before", plan.load_before},
          {"load_average_after", proc_value("/proc/loadavg")},
          {"devices", devices},
          {"opencl_environment", opencl_environment()},
          {"date", now_text()}};
}

// This session of the experiment (one command; --resume starts another): when it started and
// ended, the machine's load before and after it, and how many of the runs it measured.
nlohmann::json session_of(const Plan& plan, std::size_t measured) {
  return {{"started", plan.started},
          {"ended", now_text()},
          {"hardware_threads", std::thread::hardware_concurrency()},
          {"load_average_before", plan.load_before},
          {"load_average_after", proc_value("/proc/loadavg")},
          {"runs", measured}};
}

// What an interrupted experiment in --out left (--resume): its runs, and the sessions that
// measured them.
struct Earlier {
  nlohmann::json runs = nlohmann::json::array();
  nlohmann::json sessions = nlohmann::json::array();
};

// Written beside its place and renamed into it, so that an interrupted experiment leaves the
// last whole file, never half of one.
void write_file(const fs::path& path, const std::string& text) {
  const fs::path temporary = path.string() + ".partial";
  {
    std::ofstream out(temporary, std::ios::binary);
    out << text;
    if (!out.flush()) throw std::runtime_error("cannot write " + temporary.string());
  }
  fs::rename(temporary, path);
}

// The settings that make two experiments the same experiment (for --resume).
nlohmann::json settings_of(const Plan& plan) {
  return {{"scenes", plan.scenes},   {"repeats", plan.repeats},
          {"resolution", plan.resolution}, {"spp", plan.spp},
          {"mode", plan.mode.empty() ? "trace" : plan.mode},
          {"format", plan.format},   {"clrt_executable", plan.clrt}};
}

// results.json for `runs`: `complete` once every run of the plan is in.
nlohmann::json results_of(const Plan& plan, const Earlier& earlier, const nlohmann::json& warmups,
                          const nlohmann::json& runs, bool complete) {
  nlohmann::json results = {{"clrt", clrt_version_string()}, {"machine", machine(plan)}};
  const std::size_t session = earlier.sessions.size() + 1;
  results["sessions"] = earlier.sessions;
  results["sessions"].push_back(session_of(
      plan, static_cast<std::size_t>(std::count_if(runs.begin(), runs.end(), [&](const auto& r) {
        return r.value("session", std::size_t{1}) == session;
      }))));
  results["settings"] = settings_of(plan);
  results["complete"] = complete;
  results["warmup_runs"] = warmups;
  results["runs"] = runs;
  results["summary"] = summarize(runs);
  results["scores"] = device_scores(results["summary"]);
  results["comparisons"] = compare_variants(runs);
  results["title"] = experiment_title(results);
  return results;
}

// What an interrupted experiment in `out` left, for --resume: nothing without its results.json;
// CLI::ValidationError when it belongs to another experiment.
Earlier finished_runs(const Plan& plan) {
  const fs::path path = fs::path(plan.out_dir) / "results.json";
  if (!fs::exists(path)) return {};
  std::ifstream in(path);
  nlohmann::json earlier;
  try {
    in >> earlier;
  } catch (const nlohmann::json::exception&) {
    throw CLI::ValidationError("--resume: " + path.string() + " is not JSON");
  }
  if (!earlier.contains("settings") || earlier["settings"] != settings_of(plan) ||
      !earlier.contains("runs"))
    throw CLI::ValidationError("--resume: " + path.string() +
                               " holds another experiment (other scenes, repeats, resolution, "
                               "samples, mode, format or clrt)");
  Earlier found;
  found.runs = earlier["runs"];
  if (earlier.contains("sessions")) {
    found.sessions = earlier["sessions"];
  } else {  // written before sessions were recorded: its machine record is its one session
    const nlohmann::json& m = earlier.value("machine", nlohmann::json::object());
    found.sessions.push_back({{"started", nullptr},
                              {"ended", m.value("date", "")},
                              {"hardware_threads", m.value("hardware_threads", 0)},
                              {"load_average_before", m.value("load_average_before", "")},
                              {"load_average_after", m.value("load_average_after", "")},
                              {"runs", found.runs.size()}});
  }
  return found;
}

// clrt-experiment writes only regular files: a FIFO, device or folder in the place of one of
// its outputs is refused before any run (a FIFO would block the first read or write, and a
// rename would take its name).
void refuse_special_outputs(const std::string& out_dir) {
  for (const char* name : {"results.json", "runs.csv", "report.md", "mrays.png", "kernels.png",
                           "wavefront.png", "local-size.png"}) {
    const fs::path path = fs::path(out_dir) / name;
    std::error_code error;
    const fs::file_status status = fs::status(path, error);
    if (fs::exists(status) && !fs::is_regular_file(status))
      throw CLI::ValidationError(path.string() +
                                 " is not a regular file; clrt-experiment writes only regular "
                                 "files (remove it, or choose another --out)");
  }
}

bool same_run(const nlohmann::json& record, const Plan& plan, const RunKey& key) {
  return record["scene"] == plan.scenes[key.scene] &&
         record["device_spec"] == plan.devices[key.device].spec &&
         record["variant"] == plan.variants[key.variant].name() && record["repeat"] == key.repeat;
}

// clrt and the plot script are found from this program's own place, never from where it was
// built: installed, beside it (bin/, share/clrt/); in a build tree, where that tree put them
// (`in_build_tree`, relative), so that a copied or moved tree runs its own clrt. The first
// place, when neither exists, so that the error names it.
std::string beside_self(const fs::path& installed, const fs::path& in_build_tree) {
  std::error_code error;
  const fs::path here = fs::read_symlink("/proc/self/exe", error).parent_path();
  for (const fs::path& relative : {installed, in_build_tree})
    if (fs::exists(here / relative)) return (here / relative).lexically_normal().string();
  return (here / installed).lexically_normal().string();
}

std::string image_name(const RunKey& k, const std::string& format) {
  return "s" + std::to_string(k.scene) + "-d" + std::to_string(k.device) + "-v" +
         std::to_string(k.variant) + "-r" + std::to_string(k.repeat) + "." + format;
}

// Each configuration's warm-up runs, before any run that counts: the first run of a
// configuration builds or loads its kernels and finds the caches cold. Their records are kept
// apart ("warmup_runs"), their images not at all.
// `kept`: the runs results.json already holds (--resume), for the Ctrl-C message.
nlohmann::json warm_up(const Plan& plan, std::size_t kept) {
  const std::size_t total =
      plan.scenes.size() * plan.devices.size() * plan.variants.size() * plan.repeats;
  const fs::path images = fs::path(plan.out_dir) / "images";
  fs::create_directories(images);
  nlohmann::json warmups = nlohmann::json::array();
  for (int w = 0; w < plan.warmups; ++w)
    for (std::size_t s = 0; s < plan.scenes.size(); ++s)
      for (std::size_t d = 0; d < plan.devices.size(); ++d)
        for (std::size_t v = 0; v < plan.variants.size(); ++v) {
          const std::string image = (images / ("warmup." + plan.format)).string();
          nlohmann::json record = run_once(plan, RunKey{s, d, v, -1 - w}, image);
          fs::remove(image);
          if (interrupted) throw Interrupted{kept, total};
          record["warmup"] = true;
          std::cerr << "[warm-up] " << plan.scenes[s] << " on " << plan.devices[d].spec << ", "
                    << plan.variants[v].name() << ": "
                    << (record["exit_code"] == 0
                            ? seconds_text(record["process_seconds"].get<double>()) + " s"
                            : "failed (exit " + record["exit_code"].dump() +
                                  "): " + failure_message(record))
                    << ", not counted\n";
          warmups.push_back(record);
        }
  return warmups;
}

// Runs the whole plan, but for the runs `earlier` already holds (--resume); returns every run's
// record, each with the number of the session that measured it. results.json and runs.csv are
// rewritten after each run, so that an experiment stopped part-way (Ctrl-C) keeps what it
// finished.
nlohmann::json run_plan(const Plan& plan, const Earlier& earlier, const nlohmann::json& warmups) {
  const nlohmann::json& finished = earlier.runs;
  const std::size_t session = earlier.sessions.size() + 1;
  std::size_t kept = finished.size();
  const fs::path images = fs::path(plan.out_dir) / "images";
  fs::create_directories(images);
  const std::size_t total =
      plan.scenes.size() * plan.devices.size() * plan.variants.size() * plan.repeats;
  std::map<std::size_t, std::string> reference;  // scene -> its first successful image
  nlohmann::json runs = nlohmann::json::array();
  std::size_t done = 0;
  for (int repeat = 0; repeat < plan.repeats; ++repeat)
    for (std::size_t s = 0; s < plan.scenes.size(); ++s)
      for (std::size_t d = 0; d < plan.devices.size(); ++d)
        for (std::size_t v = 0; v < plan.variants.size(); ++v) {
          const RunKey key{s, d, v, repeat};
          const auto kept_run = std::find_if(finished.begin(), finished.end(), [&](const auto& r) {
            return same_run(r, plan, key);
          });
          if (kept_run != finished.end()) {
            if (kept_run->contains("validation") && !reference.count(s))
              reference[s] = (*kept_run)["validation"]["reference"].get<std::string>();
            runs.push_back(*kept_run);
            ++done;
            continue;
          }
          const std::string image = (images / image_name(key, plan.format)).string();
          nlohmann::json record = run_once(plan, key, image);
          if (interrupted) {
            fs::remove(image);
            throw Interrupted{kept, total};
          }
          record["session"] = session;
          std::cerr << "[" << ++done << "/" << total << "] " << plan.scenes[s] << " on "
                    << plan.devices[d].spec << ", " << plan.variants[v].name() << ": ";
          if (record["exit_code"] != 0) {
            std::cerr << "failed (exit " << record["exit_code"] << "): " << failure_message(record)
                      << "\n";
          } else if (!reference.count(s)) {
            reference[s] = image;
            record["validation"] = {{"reference", image}, {"identical", true}, {"flagged", false}};
          } else {
            record["validation"] = validate(reference[s], image);
            if (!record["validation"]["flagged"].get<bool>()) fs::remove(image);
          }
          if (record["exit_code"] == 0)
            std::cerr << record["mrays_per_second"].get<double>() << " Mrays/s"
                      << (record["validation"]["flagged"].get<bool>() ? ", image differs" : "")
                      << (short_render(record)
                              ? ", a short render (" +
                                    seconds_text(record["seconds"]["render"].get<double>()) +
                                    " s of a " +
                                    seconds_text(record["process_seconds"].get<double>()) +
                                    " s command): its Mrays/s measure start-up as much as tracing"
                              : "")
                      << "\n";
          runs.push_back(record);
          const fs::path out(plan.out_dir);
          write_file(out / "results.json",
                     results_of(plan, earlier, warmups, runs, false).dump(2) + "\n");
          write_file(out / "runs.csv", runs_csv(runs));
          kept = runs.size();
        }
  return runs;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"clrt-experiment: scenes x devices x variants x repeats, one clrt process each",
               "clrt-experiment"};
  clrt::identify_tool(
      app, {"docs/experiments.md",
            {"ray", "RAY", "nff", "NFF"},
            {{"0", "every run succeeded and every image equals its scene's first"},
             {"1", "a run failed, an image differs from its scene's first, or the experiment could "
                   "not run or write its results"},
             {"2", "a usage error, a scene that is missing, or --resume against other settings"}},
            {{"clrt-experiment scenes/cornell.ray scenes/reflect.ray --repeats 3",
              "each scene three times on the default device: results.json, runs.csv, report.md "
              "and plots in experiment/"},
             {"clrt-experiment scenes/reflect.ray --device all --integrator wavefront,megakernel",
              "both integrators on every device"}}});
  std::vector<std::string> scene_paths, device_specs = {"cpu"}, extras;
  std::string integrators = "wavefront", wavefronts, local_sizes, python = CLRT_PYTHON3;
  const std::string plot_script =
      beside_self("../share/clrt/plot_experiment.py", "plot_experiment.py");
  bool plots = true;
  Plan plan;
  plan.clrt = beside_self("clrt", CLRT_FROM_BUILT_EXPERIMENT);
  plan.resolution = "1280x720";
  plan.out_dir = "experiment";
  app.add_option("scenes", scene_paths, ".ray or .nff files, or folders of them")->required();
  app.add_option("--device", device_specs,
                 "devices to compare, as clrt --device takes them; `all` is every device "
                 "(repeatable; default cpu)");
  app.add_option("--integrator", integrators,
                 "comma-separated: " + CLI::detail::join(clrt::integrator_names(), ", "))
      ->type_name("{" + CLI::detail::join(clrt::integrator_names(), ",") + "},...")
      ->capture_default_str();
  app.add_option("--wavefront", wavefronts, "comma-separated queue sizes (default: the device's)");
  app.add_option("--local-size", local_sizes, "comma-separated work-group sizes (default: the device's)");
  app.add_option("--variant", extras, "NAME=ARGS: further clrt arguments as one more variant (repeatable)");
  app.add_option("--repeats", plan.repeats, "runs of each configuration")
      ->transform(clrt::whole_number(1, 1000))
      ->capture_default_str();
  app.add_option("--warmup", plan.warmups,
                 "runs of each configuration before those that count, reported apart")
      ->transform(clrt::whole_number(0, 100))
      ->capture_default_str();
  app.add_option("--resolution", plan.resolution, "WxH for every scene; `scene` keeps each scene's")
      ->capture_default_str();
  app.add_option("--spp", plan.spp, "samples per pixel for every scene (default: each scene's)")
      ->transform(clrt::whole_number(1, clrt::limits::kMaxSamples));
  app.add_option("--mode", plan.mode, "clrt's --mode for every run: trace (default), cast or path")
      ->transform(clrt::word_choice({"trace", "cast", "path"}));
  app.add_option("--format", plan.format, "image format clrt writes and the runner compares")
      ->transform(clrt::word_choice({"pfm", "png", "exr", "ppm"}))
      ->capture_default_str();
  app.add_option("--out", plan.out_dir, "folder for results.json, runs.csv, report.md, plots")
      ->capture_default_str();
  app.add_option("--clrt", plan.clrt, "the clrt executable")->capture_default_str();
  app.add_option("--python", python, "the Python with matplotlib that draws the plots")
      ->capture_default_str();
  app.add_flag("!--no-plots", plots, "write no plots");
  bool resume = false;
  app.add_flag("--resume", resume,
               "keep the runs an interrupted experiment of the same settings left in --out's "
               "results.json, and run only the others");
  if (const auto status = clrt::parse_tool_arguments(app, argc, argv)) return *status;
  if (plan.resolution == "scene") plan.resolution.clear();
  try {
    plan.scenes = expand_scenes(scene_paths);
    if (plan.scenes.empty()) throw CLI::ValidationError("no .ray or .nff scene found");
    for (const std::string& scene : plan.scenes)
      if (!fs::is_regular_file(scene)) throw CLI::ValidationError("no scene file " + scene);
    for (const std::string& name : split_list(integrators))
      if (!clrt::parse_integrator(name))
        throw CLI::ValidationError("--integrator takes " + CLI::detail::join(clrt::integrator_names(), ", ") +
                                   ", not '" + name + "'");
    plan.variants = expand_variants(split_list(integrators), split_list(wavefronts),
                                    split_list(local_sizes), extras);
    refuse_special_outputs(plan.out_dir);
  } catch (const CLI::Error& e) {
    std::cerr << "clrt-experiment: error: " << e.what() << "\n";
    return 2;
  }
  try {
    plan.devices = choose_devices(device_specs);
    plan.load_before = proc_value("/proc/loadavg");
    plan.started = now_text();
    Earlier earlier;
    try {
      if (resume) earlier = finished_runs(plan);
    } catch (const CLI::Error& e) {
      std::cerr << "clrt-experiment: error: " << e.what() << "\n";
      return 2;
    }
    struct sigaction action {};
    action.sa_handler = on_interrupt;  // no SA_RESTART: the wait for a run wakes and goes on
    sigemptyset(&action.sa_mask);
    sigaction(SIGINT, &action, nullptr);
    nlohmann::json warmups, runs;
    try {
      warmups = warm_up(plan, earlier.runs.size());
      runs = run_plan(plan, earlier, warmups);
    } catch (const Interrupted& stop) {
      const fs::path results = fs::path(plan.out_dir) / "results.json";
      std::cerr << "\nclrt-experiment: interrupted: ";
      if (stop.kept == 0)
        std::cerr << "no run had finished, nothing kept\n";
      else
        std::cerr << stop.kept << " of " << stop.total << " runs kept in " << results.string()
                  << "; the same command with --resume runs the other "
                  << stop.total - stop.kept << "\n";
      return 130;
    }
    const nlohmann::json results = results_of(plan, earlier, warmups, runs, true);
    const fs::path out(plan.out_dir);
    write_file(out / "results.json", results.dump(2) + "\n");
    write_file(out / "runs.csv", runs_csv(runs));
    write_file(out / "report.md", markdown_report(results));
    std::cout << markdown_report(results);
    int failed = 0, flagged = 0;
    for (const nlohmann::json& s : results["summary"]) {
      failed += s["failed"].get<int>();
      flagged += s["flagged"].get<int>();
    }
    if (plots) {
      const ProcessResult p = run_process({python, plot_script, (out / "results.json").string(),
                                           out.string()});
      if (p.exit_code != 0) {
        std::cerr << "clrt-experiment: error: the plots failed (" << python << " " << plot_script
                  << "):\n" << p.err;
        return 1;
      }
    }
    std::cerr << "clrt-experiment: wrote " << out.string() << "/results.json, runs.csv, report.md"
              << (plots ? ", plots" : "") << "\n";
    if (failed || flagged) {
      std::cerr << "clrt-experiment: " << failed << " runs failed, " << flagged
                << " images differ from their scene's first\n";
      return 1;
    }
    return 0;
  } catch (const std::exception& e) {
    std::cerr << "clrt-experiment: error: " << e.what() << "\n";
    return 1;
  }
}

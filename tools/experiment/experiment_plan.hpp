// What an experiment runs: scenes x devices x variants x repeats, each run one clrt process.
#pragma once

#include <string>
#include <vector>

namespace clrt::experiment {

// One configuration of clrt to measure; empty fields keep clrt's defaults for the device.
struct Variant {
  std::string integrator;   // "wavefront", "megakernel" or empty
  std::string wavefront;    // rays per queue, or empty
  std::string local_size;   // work-items per group, or empty
  std::string extra_name;   // a named set of further clrt arguments (--variant NAME=ARGS)
  std::vector<std::string> extra_args;

  std::string name() const;  // e.g. "megakernel wf=4096 ls=128 seed9"
  std::vector<std::string> clrt_args() const;
};

struct DeviceChoice {
  std::string spec;  // "P:D", as clrt --device takes it
  std::string name;  // the device's name, for tables
  std::string platform, driver;  // its platform's name and its driver's version, for the record
};

struct Plan {
  std::vector<std::string> scenes;
  std::vector<DeviceChoice> devices;
  std::vector<Variant> variants;
  int repeats = 3;
  int warmups = 1;          // runs of each configuration before those that count
  std::string resolution;   // WxH, or empty for each scene's own
  std::string spp;          // or empty for each scene's own
  std::string mode;         // clrt's --mode for every run, or empty for its default (trace)
  std::string format = "pfm";
  std::string clrt;         // the executable
  std::string out_dir;
  std::string load_before;  // /proc/loadavg when the experiment started, for the record
  std::string started;      // when it started (UTC), for the record
};

// Files named, and the .ray and .nff files (sorted) of folders named.
std::vector<std::string> expand_scenes(const std::vector<std::string>& paths);

// "a,b,c" -> {a, b, c}; an empty text gives one empty entry (the default).
std::vector<std::string> split_list(const std::string& text);

// Every combination of the lists, integrators outermost; `extras` are "NAME=ARGS" entries.
std::vector<Variant> expand_variants(const std::vector<std::string>& integrators,
                                     const std::vector<std::string>& wavefronts,
                                     const std::vector<std::string>& local_sizes,
                                     const std::vector<std::string>& extras);

// The devices `specs` name ("all", "cpu", "P:D", part of a name), each once, in device order.
// Throws DeviceError when one matches nothing.
std::vector<DeviceChoice> choose_devices(const std::vector<std::string>& specs);

}  // namespace clrt::experiment

// One run of an experiment: the clrt process, what it reported (--stats=json), what the runner
// measured around it, and how its image compares with the scene's first image.
#pragma once

#include <nlohmann/json.hpp>
#include <string>

#include "experiment_plan.hpp"

namespace clrt::experiment {

struct RunKey {
  std::size_t scene = 0, device = 0, variant = 0;
  int repeat = 0;
};

// Runs clrt for `key`, writing its image to `image`. The record holds the run's settings,
// "exit_code", and when it succeeded clrt's statistics plus "process_seconds" and "peak_bytes";
// when it failed, "error" with clrt's message.
nlohmann::json run_once(const Plan& plan, const RunKey& key, const std::string& image);

// What a failed run's record says went wrong: clrt's own message, the first line it wrote to
// standard error with "error:" in it (the one that names the fault: earlier lines are the device
// and progress, later ones hints such as "Run 'clrt --help' for usage."), else its last line.
std::string failure_message(const nlohmann::json& run);

// How `image` compares with `reference`: "identical" (the same bytes) or else the PSNR, the
// count of differing pixels and the largest difference, and "flagged" unless identical.
nlohmann::json validate(const std::string& reference, const std::string& image);

}  // namespace clrt::experiment

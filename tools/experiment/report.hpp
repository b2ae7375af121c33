// What an experiment's runs add up to: medians over repeats, a score per device, and the CSV
// and Markdown forms of the results.
#pragma once

#include <nlohmann/json.hpp>
#include <string>

namespace clrt::experiment {

// A render too short for its Mrays/s to measure tracing rather than start-up: under
// kShortRenderSeconds, or under kShortRenderShare of its whole command.
constexpr double kShortRenderSeconds = 0.2;
constexpr double kShortRenderShare = 0.5;
bool short_render(const nlohmann::json& run);

// A session (one command of an experiment; --resume starts another) on a busy machine: a 1-minute
// load average before its runs of at least kBusyLoadBefore x the hardware threads (other work
// held that share of the machine), or after them above kBusyLoadAfter x the hardware threads
// (more than the experiment's own clrt, which keeps every hardware thread busy, makes).
constexpr double kBusyLoadBefore = 0.5;
constexpr double kBusyLoadAfter = 1.5;
bool busy_session(const nlohmann::json& session);

// The 1-minute load average of a /proc/loadavg line ("5.65 3.10 2.00 3/400 1234"), or -1.
double one_minute_load(const std::string& loadavg);

// One entry per (scene, device, variant) that ran, in run order: the medians over its repeats
// of Mrays/s, Msamples/s, render and process seconds, device busy share, peak MiB, and of each
// kernel's device seconds, with their [min, max] in "spread" and "kernel_spread"; "runs",
// "failed", "flagged" and "short" (short_render) counts.
nlohmann::json summarize(const nlohmann::json& runs);

// The score of each device: 100 x the geometric mean over the experiment's scenes of the median
// Mrays/s of its first variant (see README "Experiments"), and in "spread" the same of the
// slowest and of the fastest repeats. Devices with a failed scene get none.
nlohmann::json device_scores(const nlohmann::json& summary);

// Each variant against the first of its scene and device (in run order): the ratio of their
// median Mrays/s, and the Mann-Whitney p-value of their repeats (rank_test.hpp) with the smallest
// p the repeats allow. One entry per (scene, device, later variant).
nlohmann::json compare_variants(const nlohmann::json& runs);

// What the experiment measured, for every report's and plot's title: the resolution, the
// samples per pixel and the devices ("1280x720, 4 spp, on 0:0 pthread-...").
std::string experiment_title(const nlohmann::json& results);

// Every run, one line each, with a header line.
std::string runs_csv(const nlohmann::json& runs);

// The sessions with their load (and a warning for a busy one), the summary, the per-kernel
// breakdown, the scores and the flagged runs as Markdown tables.
std::string markdown_report(const nlohmann::json& results);

}  // namespace clrt::experiment

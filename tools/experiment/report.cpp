#include "report.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <iomanip>
#include <map>
#include <set>
#include <sstream>

#include "rank_test.hpp"
#include "run_record.hpp"

namespace clrt::experiment {
namespace {

// The median of the repeats, and their spread.
struct Spread {
  double median = 0, min = 0, max = 0;
};

Spread spread(std::vector<double> v) {
  if (v.empty()) return {};
  std::sort(v.begin(), v.end());
  const std::size_t n = v.size();
  return {n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]), v.front(), v.back()};
}

std::string group_key(const nlohmann::json& run) {
  return run["scene"].get<std::string>() + "\n" + run["device_spec"].get<std::string>() + "\n" +
         run["variant"].get<std::string>();
}

bool succeeded(const nlohmann::json& run) { return run["exit_code"] == 0; }

std::string fixed(double v, int digits) {
  std::ostringstream out;
  out << std::fixed << std::setprecision(digits) << v;
  return out.str();
}

// `field` (a JSON pointer) over the successful runs of a group, times `scale`, as the summary's
// median `name` and its "spread" [min, max].
void summarize_field(const std::vector<const nlohmann::json*>& runs, const char* field,
                     const char* name, double scale, nlohmann::json& summary) {
  std::vector<double> v;
  for (const nlohmann::json* r : runs)
    if (succeeded(*r)) v.push_back(scale * r->at(nlohmann::json::json_pointer(field)).get<double>());
  const Spread s = spread(v);
  summary[name] = s.median;
  summary["spread"][name] = {s.min, s.max};
}

// A median with the spread of the repeats after it, "12.30 (12.10-12.50)", when there was more
// than one.
std::string with_spread(const nlohmann::json& summary, const nlohmann::json& median,
                        const nlohmann::json& range, int digits, double scale = 1) {
  std::string text = fixed(scale * median.get<double>(), digits);
  if (summary["runs"].get<int>() - summary["failed"].get<int>() > 1)
    text += " (" + fixed(scale * range[0].get<double>(), digits) + "-" +
            fixed(scale * range[1].get<double>(), digits) + ")";
  return text;
}

std::string cell(const nlohmann::json& summary, const char* name, int digits, double scale = 1) {
  return with_spread(summary, summary[name], summary["spread"][name], digits, scale);
}

std::string load_text(const nlohmann::json& session, const char* field) {
  const double load = one_minute_load(session.value(field, ""));
  return load < 0 ? std::string("?") : fixed(load, 2);
}

// Each session with its dates, load and runs; a warning under it for each busy one.
std::string sessions_section(const nlohmann::json& sessions) {
  std::ostringstream out, warnings;
  out << "The machine's 1-minute load average before and after each session (a resumed experiment "
         "has one per command):\n\n| session | started | ended | hardware threads | load before "
         "| load after | runs |\n|---:|---|---|---:|---:|---:|---:|\n";
  for (std::size_t n = 0; n < sessions.size(); ++n) {
    const nlohmann::json& s = sessions[n];
    const std::string started = s["started"].is_string() ? s["started"].get<std::string>() : "?";
    out << "| " << n + 1 << " | " << started << " | " << s.value("ended", "?") << " | "
        << s.value("hardware_threads", 0) << " | " << load_text(s, "load_average_before") << " | "
        << load_text(s, "load_average_after") << " | " << s.value("runs", 0) << " |\n";
    if (busy_session(s))
      warnings << "\n**Warning: a busy machine.** In session " << n + 1 << " the load average was "
               << load_text(s, "load_average_before") << " before and "
               << load_text(s, "load_average_after") << " after, on " << s["hardware_threads"]
               << " hardware threads: other work shared the cores with its runs, so their times "
                  "and spreads measure that work as much as clrt. Measure again on an idle "
                  "machine before trusting a difference.\n";
  }
  return out.str() + warnings.str();
}

std::string scene_name(const std::string& path) {
  return std::filesystem::path(path).filename().string();
}

// CSV fields hold scene paths and device names: quote every text field.
std::string csv_text(const std::string& s) {
  std::string out = "\"";
  for (char c : s) out += c == '"' ? std::string("\"\"") : std::string(1, c);
  return out + "\"";
}

}  // namespace

bool short_render(const nlohmann::json& run) {
  if (!succeeded(run)) return false;
  const double render = run["seconds"]["render"].get<double>();
  const double command = run["process_seconds"].get<double>();
  return render < kShortRenderSeconds || render < kShortRenderShare * command;
}

double one_minute_load(const std::string& loadavg) {
  std::istringstream in(loadavg);
  double load = -1;
  return in >> load ? load : -1;
}

bool busy_session(const nlohmann::json& session) {
  const double threads = session.value("hardware_threads", 0.0);
  if (threads <= 0) return false;
  return one_minute_load(session.value("load_average_before", "")) >= kBusyLoadBefore * threads ||
         one_minute_load(session.value("load_average_after", "")) > kBusyLoadAfter * threads;
}

nlohmann::json summarize(const nlohmann::json& runs) {
  std::vector<std::string> order;
  std::map<std::string, std::vector<const nlohmann::json*>> groups;
  for (const nlohmann::json& run : runs) {
    const std::string key = group_key(run);
    if (!groups.count(key)) order.push_back(key);
    groups[key].push_back(&run);
  }
  nlohmann::json out = nlohmann::json::array();
  for (const std::string& key : order) {
    const std::vector<const nlohmann::json*>& g = groups[key];
    const nlohmann::json& first = *g.front();
    nlohmann::json s = {{"scene", first["scene"]},
                        {"device_spec", first["device_spec"]},
                        {"device_name", first["device_name"]},
                        {"variant", first["variant"]},
                        {"runs", g.size()}};
    int failed = 0, flagged = 0, short_runs = 0;
    std::set<std::string> kernels;
    for (const nlohmann::json* r : g) {
      if (!succeeded(*r)) {
        ++failed;
        continue;
      }
      if (r->contains("validation") && (*r)["validation"]["flagged"].get<bool>()) ++flagged;
      if (short_render(*r)) ++short_runs;
      for (const auto& [name, k] : (*r)["kernels"].items()) kernels.insert(name);
    }
    s["failed"] = failed;
    s["flagged"] = flagged;
    s["short"] = short_runs;
    // The settings the device really ran with (the variant may leave them to clrt).
    for (const nlohmann::json* r : g)
      if (succeeded(*r)) {
        s["integrator"] = (*r)["integrator"];
        s["wavefront"] = (*r)["devices"][0]["wavefront"];
        s["local_size"] = (*r)["devices"][0]["local_size"];
        break;
      }
    summarize_field(g, "/mrays_per_second", "mrays_per_second", 1, s);
    summarize_field(g, "/samples_per_second", "msamples_per_second", 1e-6, s);
    summarize_field(g, "/seconds/render", "render_seconds", 1, s);
    summarize_field(g, "/process_seconds", "process_seconds", 1, s);
    summarize_field(g, "/device_busy", "device_busy", 1, s);
    summarize_field(g, "/peak_bytes", "peak_mib", 1.0 / (1024.0 * 1024.0), s);
    s["kernels"] = s["kernel_spread"] = nlohmann::json::object();
    for (const std::string& name : kernels) {
      std::vector<double> v;
      for (const nlohmann::json* r : g)
        if (succeeded(*r) && (*r)["kernels"].contains(name))
          v.push_back((*r)["kernels"][name]["share_seconds"].get<double>());
      const Spread k = spread(v);
      s["kernels"][name] = k.median;
      s["kernel_spread"][name] = {k.min, k.max};
    }
    out.push_back(s);
  }
  return out;
}

nlohmann::json device_scores(const nlohmann::json& summary) {
  if (summary.empty()) return nlohmann::json::object();
  const std::string first_variant = summary[0]["variant"];
  // The medians, and the slowest and fastest repeats, of each scene.
  std::map<std::string, std::vector<double>> rates, slowest, fastest;
  std::set<std::string> incomplete;
  std::map<std::string, std::string> names;
  for (const nlohmann::json& s : summary) {
    if (s["variant"] != first_variant) continue;
    const std::string device = s["device_spec"];
    names[device] = s["device_name"];
    if (s["failed"].get<int>() > 0 || s["mrays_per_second"].get<double>() <= 0)
      incomplete.insert(device);
    else {
      rates[device].push_back(s["mrays_per_second"]);
      slowest[device].push_back(s["spread"]["mrays_per_second"][0]);
      fastest[device].push_back(s["spread"]["mrays_per_second"][1]);
    }
  }
  const auto score = [](const std::vector<double>& values) {
    double log_sum = 0;
    for (double r : values) log_sum += std::log(r);
    return std::round(100 * std::exp(log_sum / static_cast<double>(values.size())));
  };
  nlohmann::json out = nlohmann::json::object();
  for (const auto& [device, name] : names) {
    if (incomplete.count(device)) {
      out[device] = {{"name", name}, {"score", nullptr}, {"variant", first_variant}};
      continue;
    }
    out[device] = {{"name", name},
                   {"score", score(rates[device])},
                   {"spread", {score(slowest[device]), score(fastest[device])}},
                   {"variant", first_variant}};
  }
  return out;
}

nlohmann::json compare_variants(const nlohmann::json& runs) {
  // Each (scene, device)'s variants in run order, with their successful runs' Mrays/s.
  std::map<std::string, std::vector<std::pair<std::string, std::vector<double>>>> groups;
  std::vector<std::string> order;
  for (const nlohmann::json& r : runs) {
    const std::string where = r["scene"].get<std::string>() + "\n" + r["device_spec"].get<std::string>();
    if (!groups.count(where)) order.push_back(where);
    auto& variants = groups[where];
    const std::string variant = r["variant"];
    auto it = std::find_if(variants.begin(), variants.end(),
                           [&](const auto& v) { return v.first == variant; });
    if (it == variants.end()) it = variants.insert(variants.end(), {variant, {}});
    if (succeeded(r)) it->second.push_back(r["mrays_per_second"].get<double>());
  }
  nlohmann::json out = nlohmann::json::array();
  for (const std::string& where : order) {
    const auto& variants = groups[where];
    const std::string scene = where.substr(0, where.find('\n'));
    const std::string device = where.substr(where.find('\n') + 1);
    const auto& [baseline, base_values] = variants.front();
    for (std::size_t v = 1; v < variants.size(); ++v) {
      const auto& [variant, values] = variants[v];
      nlohmann::json c = {{"scene", scene}, {"device_spec", device}, {"variant", variant},
                          {"baseline", baseline}};
      const double base = spread(base_values).median;
      c["ratio"] = base > 0 && !values.empty() ? spread(values).median / base : 0.0;
      c["p"] = mann_whitney_p(values, base_values);
      c["smallest_p"] = smallest_mann_whitney_p(static_cast<int>(values.size()),
                                                static_cast<int>(base_values.size()));
      out.push_back(c);
    }
  }
  return out;
}

std::string experiment_title(const nlohmann::json& results) {
  const nlohmann::json& settings = results["settings"];
  const std::string resolution = settings["resolution"];
  const std::string spp = settings["spp"];
  std::string devices;
  std::set<std::string> named;
  for (const nlohmann::json& s : results["summary"]) {
    const std::string device = s["device_spec"].get<std::string>() + " " +
                               s["device_name"].get<std::string>();
    if (named.insert(device).second) devices += (devices.empty() ? "" : ", ") + device;
  }
  return (resolution.empty() ? std::string("each scene's size") : resolution) + ", " +
         (spp.empty() ? std::string("each scene's samples per pixel") : spp + " spp") + ", on " +
         devices;
}

std::string runs_csv(const nlohmann::json& runs) {
  std::ostringstream out;
  out << "scene,device_spec,device,variant,repeat,exit_code,camera,reflection,refraction,shadow,"
         "total,mrays_per_s,msamples_per_s,load_s,bvh_s,kernel_build_s,render_s,write_s,total_s,"
         "process_s,device_s,device_busy,peak_mib,identical,psnr,differing_pixels,flagged\n";
  for (const nlohmann::json& r : runs) {
    out << csv_text(r["scene"]) << "," << csv_text(r["device_spec"]) << ","
        << csv_text(r["device_name"]) << "," << csv_text(r["variant"]) << "," << r["repeat"] << ","
        << r["exit_code"];
    if (!succeeded(r)) {
      out << std::string(21, ',') << "\n";
      continue;
    }
    const nlohmann::json& rays = r["rays"];
    const nlohmann::json& t = r["seconds"];
    out << "," << rays["camera"] << "," << rays["reflection"] << "," << rays["refraction"] << ","
        << rays["shadow"] << "," << rays["total"] << "," << r["mrays_per_second"] << ","
        << r["samples_per_second"].get<double>() / 1e6 << "," << t["load"] << "," << t["bvh"] << ","
        << t["kernel_build"] << "," << t["render"] << "," << t["write"] << "," << t["total"] << ","
        << r["process_seconds"] << "," << t["device"] << "," << r["device_busy"] << ","
        << r["peak_bytes"].get<double>() / (1024.0 * 1024.0);
    const nlohmann::json& v = r["validation"];
    out << "," << v["identical"] << "," << (v.contains("psnr") ? v["psnr"].dump() : "") << ","
        << (v.contains("differing_pixels") ? v["differing_pixels"].dump() : "0") << ","
        << v["flagged"] << "\n";
  }
  return out.str();
}

std::string markdown_report(const nlohmann::json& results) {
  const nlohmann::json& summary = results["summary"];
  std::ostringstream out;
  const int repeats = results["settings"]["repeats"];
  out << "# " << results["title"].get<std::string>() << "\n\n"
      << (repeats == 1 ? std::string("One run of each configuration (--repeats 1: no spread)")
                       : "Medians over " + std::to_string(repeats) +
                             " repeats, their spread (min-max) in parentheses")
      << "; " << results["clrt"].get<std::string>() << ".\n\n";
  if (results.contains("sessions")) out << sessions_section(results["sessions"]) << "\n";
  out << "| scene | device | variant | Mrays/s | Msamples/s | render s | command s | device busy "
         "| peak MiB | runs | flagged |\n|---|---|---|---:|---:|---:|---:|---:|---:|---:|---:|\n";
  for (const nlohmann::json& s : summary)
    out << "| " << scene_name(s["scene"]) << " | " << s["device_spec"].get<std::string>() << " "
        << s["device_name"].get<std::string>() << " | " << s["variant"].get<std::string>() << " | "
        << cell(s, "mrays_per_second", 2) << " | " << cell(s, "msamples_per_second", 3) << " | "
        << cell(s, "render_seconds", 3) << " | " << cell(s, "process_seconds", 3) << " | "
        << cell(s, "device_busy", 0, 100) << "% | " << cell(s, "peak_mib", 0) << " | " << s["runs"].get<int>() - s["failed"].get<int>() << "/" << s["runs"] << " | "
        << s["flagged"] << " |\n";

  std::set<std::string> kernels;
  for (const nlohmann::json& s : summary)
    for (const auto& [name, seconds] : s["kernels"].items()) kernels.insert(name);
  out << "\nDevice seconds per kernel (medians; where lanes ran kernels at once, each had an "
         "equal part of that time):\n\n| scene | device | variant |";
  for (const std::string& k : kernels) out << " " << k << " s |";
  out << "\n|---|---|---|";
  for (std::size_t k = 0; k < kernels.size(); ++k) out << "---:|";
  out << "\n";
  for (const nlohmann::json& s : summary) {
    out << "| " << scene_name(s["scene"]) << " | " << s["device_spec"].get<std::string>() << " | "
        << s["variant"].get<std::string>() << " |";
    for (const std::string& k : kernels)
      out << " "
          << (s["kernels"].contains(k) ? with_spread(s, s["kernels"][k], s["kernel_spread"][k], 4)
                                       : "")
          << " |";
    out << "\n";
  }

  out << "\n| device | score (variant: " << (summary.empty() ? "" : summary[0]["variant"].get<std::string>())
      << ") |\n|---|---:|\n";
  for (const auto& [device, s] : results["scores"].items())
    out << "| " << device << " " << s["name"].get<std::string>() << " | "
        << (s["score"].is_null()
                ? std::string("(a scene failed)")
                : fixed(s["score"], 0) + " (" + fixed(s["spread"][0], 0) + "-" +
                      fixed(s["spread"][1], 0) + ")")
        << " |\n";

  std::ostringstream flagged;
  for (const nlohmann::json& r : results["runs"]) {
    if (!succeeded(r)) {
      flagged << "- failed: " << scene_name(r["scene"]) << " on " << r["device_spec"].get<std::string>()
              << ", " << r["variant"].get<std::string>() << " (exit " << r["exit_code"]
              << "): " << failure_message(r) << "\n";
    } else if (r["validation"]["flagged"].get<bool>()) {
      const nlohmann::json& v = r["validation"];
      flagged << "- differs from the scene's first image: " << scene_name(r["scene"]) << " on "
              << r["device_spec"].get<std::string>() << ", " << r["variant"].get<std::string>()
              << ", repeat " << r["repeat"] << ": " << v["differing_pixels"]
              << " pixels differ, PSNR " << (v["psnr"].is_null() ? "inf" : fixed(v["psnr"], 2))
              << " dB\n";
    }
  }
  out << "\n" << (flagged.str().empty() ? "Every image is identical to its scene's first.\n"
                                        : "Flagged runs:\n\n" + flagged.str());
  const nlohmann::json& comparisons = results["comparisons"];
  if (!comparisons.empty()) {
    out << "\nEach variant against the first of its scene and device: the ratio of their median "
           "Mrays/s, and the two-sided p-value of the Mann-Whitney U test on their repeats (below "
           "0.05: a difference the repeats' noise is unlikely to make):\n\n| scene | device | "
           "variant | against | Mrays/s ratio | p |\n|---|---|---|---|---:|---:|\n";
    bool too_few = false;
    for (const nlohmann::json& c : comparisons) {
      out << "| " << scene_name(c["scene"]) << " | " << c["device_spec"].get<std::string>() << " | "
          << c["variant"].get<std::string>() << " | " << c["baseline"].get<std::string>() << " | "
          << fixed(c["ratio"], 3) << " | " << fixed(c["p"], 3) << " |\n";
      too_few = too_few || c["smallest_p"].get<double>() >= 0.05;
    }
    if (too_few)
      out << "\nWith these repeats the test cannot reach p < 0.05 (3 repeats of each: at best "
             "0.1); --repeats 4 or more can.\n";
  }
  const nlohmann::json& warmups = results["warmup_runs"];
  if (!warmups.empty()) {
    out << "\nWarm-up runs, not counted above (a configuration's first run builds or loads its "
           "kernels and finds the caches cold):\n\n| scene | device | variant | Mrays/s | command s "
           "|\n|---|---|---|---:|---:|\n";
    for (const nlohmann::json& w : warmups)
      out << "| " << scene_name(w["scene"]) << " | " << w["device_spec"].get<std::string>()
          << " | " << w["variant"].get<std::string>() << " | "
          << (succeeded(w) ? fixed(w["mrays_per_second"].get<double>(), 2) : "failed") << " | "
          << (succeeded(w) ? fixed(w["process_seconds"].get<double>(), 3) : "") << " |\n";
  }
  std::ostringstream short_ones;
  for (const nlohmann::json& s : summary)
    if (s["short"].get<int>() > 0)
      short_ones << "- " << scene_name(s["scene"]) << " on " << s["device_spec"].get<std::string>()
                 << ", " << s["variant"].get<std::string>() << ": " << s["short"] << " of "
                 << s["runs"] << " runs, render " << cell(s, "render_seconds", 3) << " s of a "
                 << cell(s, "process_seconds", 3) << " s command\n";
  if (!short_ones.str().empty())
    out << "\nShort renders (under " << kShortRenderSeconds << " s, or under "
        << kShortRenderShare * 100 << "% of their command): their Mrays/s measure the command's "
        << "start as much as tracing; raise --resolution or --spp for a throughput figure.\n\n"
        << short_ones.str();
  return out.str();
}

}  // namespace clrt::experiment

#include "run_record.hpp"

#include <cmath>
#include <fstream>
#include <iterator>
#include <sstream>

#include "image/compare.hpp"
#include "process_run.hpp"

namespace clrt::experiment {
namespace {

std::string file_bytes(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

std::vector<std::string> clrt_args(const Plan& plan, const RunKey& key, const std::string& image) {
  std::vector<std::string> args = {plan.clrt, plan.scenes[key.scene], "--device",
                                   plan.devices[key.device].spec, "-q", "--stats=json", "-o",
                                   image};
  if (!plan.resolution.empty()) args.insert(args.end(), {"--resolution", plan.resolution});
  if (!plan.spp.empty()) args.insert(args.end(), {"--spp", plan.spp});
  if (!plan.mode.empty()) args.insert(args.end(), {"--mode", plan.mode});
  const std::vector<std::string> variant = plan.variants[key.variant].clrt_args();
  args.insert(args.end(), variant.begin(), variant.end());
  return args;
}

}  // namespace

nlohmann::json run_once(const Plan& plan, const RunKey& key, const std::string& image) {
  const std::vector<std::string> args = clrt_args(plan, key, image);
  const ProcessResult p = run_process(args);
  nlohmann::json record = {{"scene", plan.scenes[key.scene]},
                           {"device_spec", plan.devices[key.device].spec},
                           {"device_name", plan.devices[key.device].name},
                           {"variant", plan.variants[key.variant].name()},
                           {"repeat", key.repeat},
                           {"command", args},
                           {"exit_code", p.exit_code}};
  if (p.exit_code != 0) {
    record["error"] = p.err;
    return record;
  }
  nlohmann::json stats = nlohmann::json::parse(p.out, nullptr, false);
  if (stats.is_discarded()) {
    record["exit_code"] = -1;
    record["error"] = "clrt's statistics are not JSON: " + p.out.substr(0, 200);
    return record;
  }
  record.update(stats);
  record["process_seconds"] = p.wall_seconds;
  record["peak_bytes"] = p.peak_rss_bytes;
  return record;
}

std::string failure_message(const nlohmann::json& run) {
  std::istringstream error(run.value("error", ""));
  std::string last;
  for (std::string line; std::getline(error, line);) {
    if (line.find("error:") != std::string::npos) return line;
    if (!line.empty()) last = line;
  }
  return last;
}

nlohmann::json validate(const std::string& reference, const std::string& image) {
  nlohmann::json v = {{"reference", reference}};
  if (file_bytes(reference) == file_bytes(image)) {
    v["identical"] = true;
    v["flagged"] = false;
    return v;
  }
  const ImageDifference d =
      compare_images(read_any_image(reference), read_any_image(image), 0.0);
  v["identical"] = false;
  v["flagged"] = true;
  v["differing_pixels"] = d.differing;
  v["largest_difference"] = std::isfinite(d.largest) ? nlohmann::json(d.largest) : nlohmann::json();
  v["psnr"] = std::isfinite(d.psnr) ? nlohmann::json(d.psnr) : nlohmann::json();
  return v;
}

}  // namespace clrt::experiment

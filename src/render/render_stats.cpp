#include "render/render_stats.hpp"

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <nlohmann/json.hpp>
#include <sstream>

namespace clrt {
namespace {

double per_second(std::uint64_t count, double seconds) {
  return seconds > 0 ? static_cast<double>(count) / seconds : 0.0;
}

}  // namespace

const char* ray_kind_name(unsigned kind) {
  static const char* const names[CLRT_RAY_KINDS] = {"camera", "reflection", "refraction", "shadow"};
  return kind < CLRT_RAY_KINDS ? names[kind] : "unknown";
}

std::uint64_t RenderStats::total_rays() const {
  std::uint64_t sum = 0;
  for (std::uint64_t r : rays) sum += r;
  return sum;
}

double RenderStats::device_seconds() const {
  double sum = 0;
  for (const auto& [name, k] : kernels) sum += k.device_seconds;
  return sum;
}

double RenderStats::frames_per_second() const {
  return per_second(frames, render_seconds + write_seconds);
}

double RenderStats::device_busy() const {
  if (devices.empty() || render_seconds <= 0) return 0;
  double sum = 0;
  for (const DeviceReport& d : devices) sum += d.busy_seconds;
  return sum / static_cast<double>(devices.size()) / render_seconds;
}

double RenderStats::frame_share(const DeviceReport& device) const {
  std::uint64_t all = 0;
  for (const DeviceReport& d : devices) all += d.camera_samples;
  return all ? static_cast<double>(device.camera_samples) / static_cast<double>(all) : 0.0;
}

void RenderStats::merge(const RenderStats& o) {
  devices.insert(devices.end(), o.devices.begin(), o.devices.end());
  for (unsigned k = 0; k < CLRT_RAY_KINDS; ++k) rays[k] += o.rays[k];
  if (passes.size() < o.passes.size()) passes.resize(o.passes.size());
  for (std::size_t i = 0; i < o.passes.size(); ++i) {
    passes[i].rays += o.passes[i].rays;
    passes[i].shadow_rays += o.passes[i].shadow_rays;
    passes[i].max_queue = std::max(passes[i].max_queue, o.passes[i].max_queue);
    passes[i].device_seconds += o.passes[i].device_seconds;
  }
  for (const auto& [name, k] : o.kernels) {
    kernels[name].launches += k.launches;
    kernels[name].device_seconds += k.device_seconds;
    kernels[name].share_seconds += k.share_seconds;
  }
  waves += o.waves;
  wave_restarts += o.wave_restarts;
  sample_rounds = std::max(sample_rounds, o.sample_rounds);
  device_bytes += o.device_bytes;
}

std::string RenderStats::to_text() const {
  std::ostringstream out;
  out << std::fixed << std::setprecision(3);
  out << "clrt:          " << version << "\n";
  out << "scene:         " << scene << " (" << width << "x" << height << ", " << samples_per_pixel
      << (samples_per_pixel == 1 ? " sample" : " samples") << " per pixel";
  if (sample_rounds > 1) out << " in " << sample_rounds << " rounds";
  out << ")\n";
  for (const DeviceReport& d : devices)
    out << "device:        " << d.name << " (" << d.platform << ", driver " << d.driver << ", "
        << d.opencl_c << "; local size " << d.local_size << ", wavefront " << d.wavefront
        << ", lanes " << d.lanes << ")"
        << (devices.size() > 1 ? ", " + std::to_string(std::lround(100 * frame_share(d))) +
                                     "% of the frame"
                               : std::string())
        << "\n";
  out << "integrator:    " << integrator << "\n";
  out << "rays:          " << total_rays() << " (";
  for (unsigned k = 0; k < CLRT_RAY_KINDS; ++k)
    out << (k ? ", " : "") << ray_kind_name(k) << " " << rays[k];
  out << ")\n";
  out << "throughput:    " << std::setprecision(2) << per_second(total_rays(), render_seconds) / 1e6
      << " Mrays/s, " << per_second(camera_samples(), render_seconds) / 1e6
      << " Msamples/s over the render time; devices busy " << std::setprecision(0)
      << 100 * device_busy() << "% of it\n"
      << std::setprecision(3);
  if (frames > 1)
    out << "frames:        " << frames << ", " << std::setprecision(2) << frames_per_second()
        << " frames/s (render and write)\n"
        << std::setprecision(3);
  out << "time (s):      load " << load_seconds << ", bvh " << bvh_seconds << ", kernel build "
      << build_seconds << ", render " << render_seconds << ", write " << write_seconds
      << ", total " << total_seconds << "\n";
  out << "bvh:           " << bvh_seconds << " s to build, " << (bvh_bytes >> 10)
      << " KiB BVH table (nodes and leaf data); scene tables " << (geometry_bytes >> 10)
      << " KiB in all\n";
  out << "waves:         " << waves << " (restarts after a queue overflow: " << wave_restarts
      << "), device memory " << (device_bytes >> 20) << " MiB, peak process memory "
      << (peak_host_bytes >> 20) << " MiB\n";
  if (!passes.empty()) {
    out << "passes:        pass      rays    shadow  max queue  device s\n";
    for (std::size_t i = 0; i < passes.size(); ++i)
      out << "               " << std::setw(4) << i << std::setw(10) << passes[i].rays
          << std::setw(10) << passes[i].shadow_rays << std::setw(11) << passes[i].max_queue
          << std::setw(10) << passes[i].device_seconds << "\n";
  }
  out << "kernels:       name                launches  device s   share s\n";
  for (const auto& [name, k] : kernels)
    out << "               " << std::left << std::setw(20) << name << std::right << std::setw(8)
        << k.launches << std::setw(10) << k.device_seconds << std::setw(10) << k.share_seconds
        << "\n";
  return out.str();
}

nlohmann::json RenderStats::to_json() const {
  using nlohmann::json;
  json j;
  j["clrt"] = version;
  j["scene"] = scene;
  j["width"] = width;
  j["height"] = height;
  j["samples_per_pixel"] = samples_per_pixel;
  j["sample_rounds"] = sample_rounds;
  j["integrator"] = integrator;
  j["devices"] = json::array();
  for (const DeviceReport& d : devices)
    j["devices"].push_back({{"platform", d.platform},
                            {"name", d.name},
                            {"driver", d.driver},
                            {"opencl_c", d.opencl_c},
                            {"class", d.device_class},
                            {"local_size", d.local_size},
                            {"wavefront", d.wavefront},
                            {"lanes", d.lanes},
                            {"busy_seconds", d.busy_seconds},
                            {"camera_samples", d.camera_samples},
                            {"frame_share", frame_share(d)}});
  json by_kind = json::object();
  for (unsigned k = 0; k < CLRT_RAY_KINDS; ++k) by_kind[ray_kind_name(k)] = rays[k];
  by_kind["total"] = total_rays();
  j["rays"] = by_kind;
  j["mrays_per_second"] = per_second(total_rays(), render_seconds) / 1e6;
  j["samples_per_second"] = per_second(camera_samples(), render_seconds);
  j["device_busy"] = device_busy();
  j["frames"] = frames;
  j["frames_per_second"] = frames_per_second();
  j["seconds"] = {{"load", load_seconds},     {"bvh", bvh_seconds},
                  {"kernel_build", build_seconds}, {"render", render_seconds},
                  {"write", write_seconds},   {"total", total_seconds},
                  {"device", device_seconds()}};
  j["waves"] = waves;
  j["wave_restarts"] = wave_restarts;
  j["bytes"] = {{"device", device_bytes},
                {"peak_host", peak_host_bytes},
                {"geometry", geometry_bytes},
                {"bvh", bvh_bytes}};
  j["passes"] = json::array();
  for (const PassStats& p : passes)
    j["passes"].push_back({{"rays", p.rays},
                           {"shadow_rays", p.shadow_rays},
                           {"max_queue", p.max_queue},
                           {"device_seconds", p.device_seconds}});
  j["kernels"] = json::object();
  for (const auto& [name, k] : kernels)
    j["kernels"][name] = {{"launches", k.launches},
                          {"device_seconds", k.device_seconds},
                          {"share_seconds", k.share_seconds}};
  return j;
}

}  // namespace clrt

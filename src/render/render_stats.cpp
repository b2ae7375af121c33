#include "render/render_stats.hpp"

#include <algorithm>
#include <iomanip>
#include <sstream>

namespace clrt {
namespace {

double mrays_per_second(std::uint64_t rays, double seconds) {
  return seconds > 0 ? static_cast<double>(rays) / seconds / 1e6 : 0.0;
}

// JSON strings here are device and kernel names: escape what JSON requires.
std::string json_string(const std::string& s) {
  std::string out = "\"";
  for (char c : s) {
    if (c == '"' || c == '\\') {
      out += '\\';
      out += c;
    } else if (static_cast<unsigned char>(c) < 0x20) {
      out += ' ';
    } else {
      out += c;
    }
  }
  return out + "\"";
}

}  // namespace

void RenderStats::merge(const RenderStats& o) {
  if (!o.device.empty()) device += (device.empty() ? "" : ", ") + o.device;
  camera_rays += o.camera_rays;
  reflection_rays += o.reflection_rays;
  refraction_rays += o.refraction_rays;
  shadow_rays += o.shadow_rays;
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
  }
  waves += o.waves;
  wave_restarts += o.wave_restarts;
  wavefront = std::max(wavefront, o.wavefront);
  device_bytes += o.device_bytes;
  build_seconds = std::max(build_seconds, o.build_seconds);
}

std::string RenderStats::to_text() const {
  std::ostringstream out;
  out << std::fixed << std::setprecision(3);
  out << "device:        " << device << "\n";
  out << "rays:          " << total_rays() << " (camera " << camera_rays << ", shadow " << shadow_rays
      << ", reflection " << reflection_rays << ", refraction " << refraction_rays << ")\n";
  out << "throughput:    " << std::setprecision(2) << mrays_per_second(total_rays(), render_seconds)
      << " Mrays/s over the render time\n"
      << std::setprecision(3);
  out << "time (s):      load " << load_seconds << ", bvh " << bvh_seconds << ", kernel build "
      << build_seconds << ", render " << render_seconds << ", write " << write_seconds
      << ", total " << total_seconds << "\n";
  out << "bvh:           " << bvh_seconds << " s to build, " << (bvh_bytes >> 10)
      << " KiB BVH table (nodes and leaf data); scene tables " << (geometry_bytes >> 10)
      << " KiB in all\n";
  out << "waves:         " << waves << " (restarts after a queue overflow: " << wave_restarts
      << "), wavefront " << wavefront << " rays, device memory " << (device_bytes >> 20)
      << " MiB, peak process memory " << (peak_host_bytes >> 20) << " MiB\n";
  out << "passes:        pass      rays    shadow  max queue  device s\n";
  for (std::size_t i = 0; i < passes.size(); ++i)
    out << "               " << std::setw(4) << i << std::setw(10) << passes[i].rays
        << std::setw(10) << passes[i].shadow_rays << std::setw(11) << passes[i].max_queue
        << std::setw(10) << passes[i].device_seconds << "\n";
  out << "kernels:       name                launches  device s\n";
  for (const auto& [name, k] : kernels)
    out << "               " << std::left << std::setw(20) << name << std::right << std::setw(8)
        << k.launches << std::setw(10) << k.device_seconds << "\n";
  return out.str();
}

std::string RenderStats::to_json() const {
  std::ostringstream out;
  out << std::setprecision(6);
  out << "{\"device\": " << json_string(device) << ", \"rays\": {\"camera\": " << camera_rays
      << ", \"shadow\": " << shadow_rays << ", \"reflection\": " << reflection_rays
      << ", \"refraction\": " << refraction_rays << ", \"total\": " << total_rays()
      << "}, \"mrays_per_second\": " << mrays_per_second(total_rays(), render_seconds)
      << ", \"seconds\": {\"load\": " << load_seconds << ", \"bvh\": " << bvh_seconds
      << ", \"kernel_build\": " << build_seconds << ", \"render\": " << render_seconds
      << ", \"write\": " << write_seconds << ", \"total\": " << total_seconds
      << "}, \"waves\": " << waves << ", \"wave_restarts\": " << wave_restarts
      << ", \"wavefront\": " << wavefront << ", \"device_bytes\": " << device_bytes
      << ", \"peak_host_bytes\": " << peak_host_bytes << ", \"geometry_bytes\": " << geometry_bytes
      << ", \"bvh_bytes\": " << bvh_bytes
      << ", \"passes\": [";
  for (std::size_t i = 0; i < passes.size(); ++i)
    out << (i ? ", " : "") << "{\"rays\": " << passes[i].rays << ", \"shadow_rays\": "
        << passes[i].shadow_rays << ", \"max_queue\": " << passes[i].max_queue
        << ", \"device_seconds\": " << passes[i].device_seconds << "}";
  out << "], \"kernels\": {";
  bool first = true;
  for (const auto& [name, k] : kernels) {
    out << (first ? "" : ", ") << json_string(name) << ": {\"launches\": " << k.launches
        << ", \"device_seconds\": " << k.device_seconds << "}";
    first = false;
  }
  out << "}}\n";
  return out.str();
}

}  // namespace clrt

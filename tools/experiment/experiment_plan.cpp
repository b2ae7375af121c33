#include "experiment_plan.hpp"

#include <algorithm>
#include <filesystem>
#include <sstream>

#include "device/device_select.hpp"

namespace clrt::experiment {

std::string Variant::name() const {
  std::string out = integrator.empty() ? "wavefront" : integrator;
  if (!wavefront.empty()) out += " wf=" + wavefront;
  if (!local_size.empty()) out += " ls=" + local_size;
  if (!extra_name.empty()) out += " " + extra_name;
  return out;
}

std::vector<std::string> Variant::clrt_args() const {
  std::vector<std::string> args;
  if (!integrator.empty()) args.insert(args.end(), {"--integrator", integrator});
  if (!wavefront.empty()) args.insert(args.end(), {"--wavefront", wavefront});
  if (!local_size.empty()) args.insert(args.end(), {"--local-size", local_size});
  args.insert(args.end(), extra_args.begin(), extra_args.end());
  return args;
}

std::vector<std::string> expand_scenes(const std::vector<std::string>& paths) {
  namespace fs = std::filesystem;
  std::vector<std::string> out;
  for (const std::string& p : paths) {
    if (!fs::is_directory(p)) {
      out.push_back(p);
      continue;
    }
    std::vector<std::string> found;
    for (const auto& e : fs::directory_iterator(p))
      if (e.path().extension() == ".ray" || e.path().extension() == ".nff")
        found.push_back(e.path().string());
    std::sort(found.begin(), found.end());
    out.insert(out.end(), found.begin(), found.end());
  }
  return out;
}

std::vector<std::string> split_list(const std::string& text) {
  std::vector<std::string> out;
  std::stringstream in(text);
  std::string item;
  while (std::getline(in, item, ',')) out.push_back(item);
  if (out.empty()) out.emplace_back();
  return out;
}

namespace {

std::vector<std::string> words(const std::string& text) {
  std::istringstream in(text);
  std::vector<std::string> out;
  for (std::string w; in >> w;) out.push_back(w);
  return out;
}

}  // namespace

std::vector<Variant> expand_variants(const std::vector<std::string>& integrators,
                                     const std::vector<std::string>& wavefronts,
                                     const std::vector<std::string>& local_sizes,
                                     const std::vector<std::string>& extras) {
  std::vector<std::string> extra_list = extras;
  if (extra_list.empty()) extra_list.emplace_back();
  std::vector<Variant> out;
  for (const std::string& integrator : integrators)
    for (const std::string& wavefront : wavefronts)
      for (const std::string& local_size : local_sizes)
        for (const std::string& extra : extra_list) {
          Variant v{integrator, wavefront, local_size, {}, {}};
          const auto eq = extra.find('=');
          v.extra_name = extra.substr(0, eq);
          if (eq != std::string::npos) v.extra_args = words(extra.substr(eq + 1));
          out.push_back(v);
        }
  return out;
}

std::vector<DeviceChoice> choose_devices(const std::vector<std::string>& specs) {
  std::vector<DeviceChoice> out;
  for (const std::string& spec : specs)
    for (const DeviceEntry& e : select_devices(spec)) {
      const std::string id = std::to_string(e.platform_index) + ":" + std::to_string(e.device_index);
      const bool seen = std::any_of(out.begin(), out.end(),
                                    [&](const DeviceChoice& d) { return d.spec == id; });
      if (!seen)
        out.push_back({id, e.device.name(), e.device.platform().name(), e.device.driver_version()});
    }
  return out;
}

}  // namespace clrt::experiment

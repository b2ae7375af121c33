#include "mpi/rank_devices.hpp"

#include <algorithm>
#include <cctype>

namespace clrt::mpi {

std::vector<DeviceEntry> rank_devices(const std::string& spec, int local_rank) {
  std::string lower = spec;
  std::transform(lower.begin(), lower.end(), lower.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  if (lower != "gpu") return select_devices(spec);
  std::vector<DeviceEntry> gpus;
  for (const DeviceEntry& e : enumerate_devices())
    if (e.device.type() & CL_DEVICE_TYPE_GPU) gpus.push_back(e);
  if (gpus.empty()) return select_devices(spec);  // its error names the devices that exist
  return {gpus[static_cast<std::size_t>(local_rank) % gpus.size()]};
}

}  // namespace clrt::mpi

// The device a rank renders on. `--device gpu` on a node with several GPUs gives each rank of the
// node its own: the local rank's GPU, counting round (ranks 0..k-1 of a node with k GPUs get
// GPUs 0..k-1). Any other spec means what it means to clrt.
#pragma once

#include <string>
#include <vector>

#include "device/device_select.hpp"

namespace clrt::mpi {

std::vector<DeviceEntry> rank_devices(const std::string& spec, int local_rank);

}  // namespace clrt::mpi

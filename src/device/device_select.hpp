// Finding OpenCL devices and choosing them from a --device SPEC.
#pragma once

#include <string>
#include <vector>

#include "device/opencl.hpp"

namespace clrt {

struct DeviceEntry {
  int platform_index = 0;
  int device_index = 0;  // within its platform
  compute::device device;
};

// Every device of every platform, in platform then device order. Throws DeviceError when the
// OpenCL loader finds no platform.
std::vector<DeviceEntry> enumerate_devices();

// SPEC is `cpu`, `gpu`, `all`, `P:D` (platform and device index) or a case-insensitive
// substring of a device name. `cpu` and `gpu` take the first device of that type. Throws
// DeviceError naming the spec and the devices that exist when nothing matches.
std::vector<DeviceEntry> select_devices(const std::string& spec);

// "P:D  NAME (TYPE, N compute units, M MiB, OpenCL C X) on PLATFORM"
std::string describe_device(const DeviceEntry& entry);

// The line a render names its device with, at most `columns` wide: "device P:D NAME (TYPE, N
// units, M GiB) on PLATFORM", the device's name cut short ("...") when the line would be wider.
std::string device_line(const DeviceEntry& entry, std::size_t columns = 80);

// The --list-devices table.
std::string device_table(const std::vector<DeviceEntry>& devices);

}  // namespace clrt

#include "device/device_select.hpp"

#include <algorithm>
#include <cctype>
#include <sstream>

namespace clrt {
namespace {

std::string lower(std::string s) {
  std::transform(s.begin(), s.end(), s.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return s;
}

std::string type_name(const compute::device& d) {
  const cl_device_type type = d.type();
  if (type & CL_DEVICE_TYPE_GPU) return "GPU";
  if (type & CL_DEVICE_TYPE_CPU) return "CPU";
  if (type & CL_DEVICE_TYPE_ACCELERATOR) return "accelerator";
  return "other";
}

bool all_digits(const std::string& s) {
  return std::all_of(s.begin(), s.end(), [](unsigned char c) { return std::isdigit(c); });
}

// A spec "WHERE:D" (D a device index of at most 6 digits, WHERE non-empty), split at its last
// colon.
bool split_device_spec(const std::string& spec, std::string& where, int& device) {
  const auto colon = spec.rfind(':');
  if (colon == std::string::npos || colon == 0 || colon + 1 == spec.size()) return false;
  const std::string index = spec.substr(colon + 1);
  if (index.size() > 6 || !all_digits(index)) return false;
  where = spec.substr(0, colon);
  device = std::stoi(index);
  return true;
}

// "P:D": platform and device index, as --list-devices prints them.
bool parse_index_pair(const std::string& spec, int& platform, int& device) {
  std::string where;
  if (!split_device_spec(spec, where, device) || where.size() > 6 || !all_digits(where))
    return false;
  platform = std::stoi(where);
  return true;
}

// "NAME:D": a word naming a platform (part of its name or vendor, as "pocl", "intel") and a
// device index within it, a spelling that stays the same whatever order the ICD loader lists
// the platforms in.
bool parse_named_pair(const std::string& spec, std::string& platform, int& device) {
  std::string where;
  if (!split_device_spec(spec, where, device) || all_digits(where)) return false;
  platform = lower(where);
  return true;
}

std::vector<DeviceEntry> matching(const std::vector<DeviceEntry>& all, const std::string& spec) {
  std::vector<DeviceEntry> out;
  const std::string key = lower(spec);
  int platform = 0, device = 0;
  const bool indexed = parse_index_pair(spec, platform, device);
  std::string platform_word;
  int named_device = 0;
  const bool named = !indexed && parse_named_pair(spec, platform_word, named_device);
  for (const DeviceEntry& e : all) {
    const cl_device_type type = e.device.type();
    const bool match =
        key == "all" || (key == "cpu" && (type & CL_DEVICE_TYPE_CPU)) ||
        (key == "gpu" && (type & CL_DEVICE_TYPE_GPU)) ||
        (indexed && e.platform_index == platform && e.device_index == device) ||
        (named && e.device_index == named_device &&
         (lower(e.device.platform().name()).find(platform_word) != std::string::npos ||
          lower(e.device.platform().vendor()).find(platform_word) != std::string::npos)) ||
        (!indexed && !named && key != "cpu" && key != "gpu" &&
         (lower(e.device.name()).find(key) != std::string::npos ||
          lower(e.device.platform().name()).find(key) != std::string::npos));
    if (match) out.push_back(e);
  }
  // `cpu` is PoCL's CPU device where PoCL is installed, whatever other platform the ICD loader
  // lists first: the implementation the docs measure and the tests check (docs/devices.md).
  if (key == "cpu" && out.size() > 1) {
    const auto pocl = std::find_if(out.begin(), out.end(), [](const DeviceEntry& e) {
      return lower(e.device.platform().name()).find("portable computing language") !=
             std::string::npos;
    });
    if (pocl != out.end()) std::rotate(out.begin(), pocl, pocl + 1);
  }
  if ((key == "cpu" || key == "gpu") && out.size() > 1) out.resize(1);
  return out;
}

}  // namespace

// CL_PLATFORM_NOT_FOUND_KHR of cl_khr_icd, which the headers declare only with cl_ext.h.
constexpr cl_int kPlatformNotFound = -1001;

std::vector<DeviceEntry> enumerate_devices() {
  std::vector<compute::platform> platforms;
  try {
    platforms = compute::system::platforms();
  } catch (const compute::opencl_error& e) {
    // The ICD loader reports "no platform" as an error code; any other code is a real failure.
    if (e.error_code() != kPlatformNotFound)
      throw DeviceError("cannot list the OpenCL platforms: " + e.error_string() + " (error " +
                        std::to_string(e.error_code()) + ")");
  }
  if (platforms.empty())
    throw DeviceError(
        "no OpenCL platform found: install an OpenCL driver (e.g. Debian's pocl-opencl-icd) "
        "and check /etc/OpenCL/vendors");
  std::vector<DeviceEntry> out;
  for (std::size_t p = 0; p < platforms.size(); ++p) {
    std::vector<compute::device> devices;
    try {
      devices = platforms[p].devices();
    } catch (const compute::opencl_error&) {
      continue;  // a platform with no device answers CL_DEVICE_NOT_FOUND
    }
    for (std::size_t d = 0; d < devices.size(); ++d)
      out.push_back({static_cast<int>(p), static_cast<int>(d), devices[d]});
  }
  return out;
}

std::vector<DeviceEntry> select_devices(const std::string& spec) {
  const std::vector<DeviceEntry> all = enumerate_devices();
  std::vector<DeviceEntry> chosen = matching(all, spec);
  if (chosen.empty()) {
    std::string message = "no OpenCL device matches --device " + spec + "; the devices are:\n";
    message += all.empty() ? "  (none)\n" : device_table(all);
    throw DeviceError(message);
  }
  return chosen;
}

std::string describe_device(const DeviceEntry& e) {
  const compute::device& d = e.device;
  std::ostringstream out;
  out << e.platform_index << ':' << e.device_index << "  " << d.name() << " (" << type_name(d)
      << ", " << d.compute_units() << " compute units, " << (d.global_memory_size() >> 20)
      << " MiB, " << d.get_info<std::string>(CL_DEVICE_OPENCL_C_VERSION) << ") on "
      << d.platform().name();
  return out.str();
}

namespace {

// `text` cut to `width` characters, the cut shown by "...".
std::string shortened(const std::string& text, std::size_t width) {
  if (text.size() <= width) return text;
  return width > 3 ? text.substr(0, width - 3) + "..." : text.substr(0, width);
}

}  // namespace

std::string device_line(const DeviceEntry& e, std::size_t columns) {
  const compute::device& d = e.device;
  std::ostringstream details;
  details.precision(1);
  details << std::fixed << " (" << type_name(d) << ", " << d.compute_units() << " units, "
          << static_cast<double>(d.global_memory_size()) / (1 << 30) << " GiB) on ";
  const std::string head = "device " + std::to_string(e.platform_index) + ":" +
                           std::to_string(e.device_index) + " ";
  const std::size_t fixed_part = head.size() + details.str().size();
  const std::size_t room = columns > fixed_part ? columns - fixed_part : 0;
  // The device's name matters most; the platform gives way first, to no less than 12 characters.
  const std::string name = d.name(), platform = d.platform().name();
  const std::size_t platform_room =
      name.size() + platform.size() <= room ? platform.size()
                                            : std::max<std::size_t>(12, room > name.size() ? room - name.size() : 0);
  const std::string short_platform = shortened(platform, platform_room);
  const std::size_t name_room = room > short_platform.size() ? room - short_platform.size() : 0;
  return (head + shortened(name, name_room) + details.str() + short_platform).substr(0, columns);
}

std::string device_table(const std::vector<DeviceEntry>& devices) {
  std::string out;
  for (const DeviceEntry& e : devices) out += "  " + describe_device(e) + "\n";
  return out;
}

}  // namespace clrt

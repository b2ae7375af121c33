#include "scene/memory_limit.hpp"

#include <sys/resource.h>

#include <algorithm>
#include <fstream>
#include <sstream>
#include <utility>

namespace clrt {
namespace {

std::uint64_t soft_limit(int resource) {
  struct rlimit limit {};
  if (::getrlimit(resource, &limit) != 0 || limit.rlim_cur == RLIM_INFINITY) return UINT64_MAX;
  return static_cast<std::uint64_t>(limit.rlim_cur);
}

// The value after `key` in a "Key: 123 kB" file, in bytes; UINT64_MAX when absent.
std::uint64_t kib_field(const std::string& path, const std::string& key) {
  std::ifstream file(path);
  std::string word;
  std::uint64_t kib = 0;
  std::string line;
  while (std::getline(file, line)) {
    std::istringstream fields(line);
    if (fields >> word && word == key && fields >> kib) return kib * 1024;
  }
  return UINT64_MAX;
}

// A cgroup file holding one number or "max"; UINT64_MAX for "max" or when unreadable.
std::uint64_t cgroup_value(const std::string& path) {
  std::ifstream file(path);
  std::uint64_t value = 0;
  if (!(file >> value)) return UINT64_MAX;
  return value;
}

// The cgroup v2 path of this process ("0::/user.slice/..."), empty when it has none.
std::string own_cgroup(const std::string& proc) {
  std::ifstream file(proc + "/self/cgroup");
  std::string line;
  while (std::getline(file, line))
    if (line.rfind("0::", 0) == 0) return line.substr(3);
  return {};
}

// What memory.max leaves at `path` and every level above it, up to the root.
std::uint64_t cgroup_room(const MemorySources& s, std::string path) {
  std::uint64_t room = UINT64_MAX;
  while (!path.empty() && path != "/") {
    const std::string dir = s.cgroup_root + path;
    const std::uint64_t max = cgroup_value(dir + "/memory.max");
    if (max != UINT64_MAX) {
      const std::uint64_t current = cgroup_value(dir + "/memory.current");
      const std::uint64_t used = current == UINT64_MAX ? 0 : current;
      room = std::min(room, max > used ? max - used : 0);
    }
    path = path.substr(0, path.find_last_of('/'));
  }
  return room;
}

// What a process limit leaves once the process's own `used` bytes are counted.
std::uint64_t room_under(std::uint64_t limit, std::uint64_t used) {
  if (limit == UINT64_MAX) return UINT64_MAX;
  if (used == UINT64_MAX) return limit;
  return limit > used ? limit - used : 0;
}

}  // namespace

MemorySources system_memory_sources() {
  MemorySources s;
  s.address_space_limit = soft_limit(RLIMIT_AS);
  s.data_limit = soft_limit(RLIMIT_DATA);
  return s;
}

MemoryLimit memory_limit(const MemorySources& s) {
  const std::string status = s.proc + "/self/status";
  const std::pair<std::uint64_t, const char*> candidates[] = {
      {kib_field(s.proc + "/meminfo", "MemAvailable:"), "MemAvailable"},
      {room_under(s.address_space_limit, kib_field(status, "VmSize:")), "RLIMIT_AS, ulimit -v"},
      {room_under(s.data_limit, kib_field(status, "VmData:")), "RLIMIT_DATA, ulimit -d"},
      {cgroup_room(s, own_cgroup(s.proc)), "the cgroup's memory.max"},
  };
  MemoryLimit least;
  for (const auto& [bytes, source] : candidates)
    if (bytes < least.bytes) least = {bytes, source};
  return least;
}

std::string mebibytes(std::uint64_t bytes) {
  std::ostringstream out;
  out.precision(1);
  out << std::fixed << static_cast<double>(bytes) / (1024.0 * 1024.0) << " MiB";
  return out.str();
}

}  // namespace clrt

// How much more memory this process may take: the least of what the machine has free
// (MemAvailable), what its own limits leave (RLIMIT_AS, RLIMIT_DATA, as `ulimit -v` and `-d` set
// them) and what its cgroup v2 leaves (memory.max less memory.current, at its level and every
// level above it: a container's limit).
#pragma once

#include <cstdint>
#include <string>

namespace clrt {

// Where the figures are read; tests point them at files of their own.
struct MemorySources {
  std::string proc = "/proc";  // meminfo, self/status (VmSize, VmData), self/cgroup
  std::string cgroup_root = "/sys/fs/cgroup";
  std::uint64_t address_space_limit = UINT64_MAX;  // RLIMIT_AS's soft limit; UINT64_MAX: none
  std::uint64_t data_limit = UINT64_MAX;           // RLIMIT_DATA's
};

// This process's sources, its limits as getrlimit gives them.
MemorySources system_memory_sources();

struct MemoryLimit {
  std::uint64_t bytes = UINT64_MAX;  // UINT64_MAX when nothing could be read
  std::string source;                // which limit it is, for messages: "MemAvailable", ...
};

MemoryLimit memory_limit(const MemorySources& sources = system_memory_sources());

// `bytes` for messages: "1234.5 MiB".
std::string mebibytes(std::uint64_t bytes);

}  // namespace clrt

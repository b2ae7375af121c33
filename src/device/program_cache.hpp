// Compiled programs kept on disk between runs, for drivers that keep none of their own. (PoCL
// keeps one; loading clrt's binary would spare its lookup, about 50 ms, but making the binary
// costs PoCL seconds: src/device/device_context.cpp.)
// The cache is an optimisation only: anything wrong with it (no folder, a stale or damaged file,
// a binary the driver refuses) falls back to building from source. Each entry carries a checksum
// of its payload, is written with fsync before it is renamed into place, and is read only when
// it is a regular file of plausible size whose checksum matches.
//
// Where: $CLRT_CACHE_DIR, else $XDG_CACHE_HOME/clrt, else $HOME/.cache/clrt; CLRT_CACHE_DIR set
// but empty turns it off. For a driver that keeps compiled kernels itself, only a folder named by
// CLRT_CACHE_DIR is used: there a first build costs more with clrt's cache than without. A file is named by a hash of everything the binary depends on (source,
// options, platform, device and driver) and holds a second, independent hash of the same, so a
// collision of names reads as a miss.
#pragma once

#include <filesystem>
#include <optional>
#include <string>

namespace clrt {

class ProgramCache {
 public:
  // The folder from the environment, or none when caching is off or there is no home, and for
  // a driver that `keeps_compiled_kernels`, none unless CLRT_CACHE_DIR names one.
  static std::optional<std::filesystem::path> folder_from_environment(bool keeps_compiled_kernels);

  // `identity`: the text that decides the binary (source, options, device description).
  ProgramCache(std::filesystem::path folder, const std::string& identity);

  // The payload stored for this identity, if the entry is whole.
  std::optional<std::string> load() const;
  // Best effort and atomic: another process may store the same entry at the same time.
  void store(const std::string& payload) const;
  void forget() const;

  const std::filesystem::path& file() const { return file_; }

 private:
  std::filesystem::path folder_, file_;
  std::string check_;
};

}  // namespace clrt

// Compiled programs kept on disk between runs. For a driver that keeps compiled kernels of its
// own (PoCL), a program missing here is built from its source through the driver's cache and its
// binary made afterwards, in the background (background_store.hpp); for others the first build
// stores it.
// The cache is an optimisation only: anything wrong with it (no folder, a stale or damaged file,
// a binary the driver refuses) falls back to building from source. Each entry carries a checksum
// of its payload, is written with fsync before it is renamed into place, and is read only when
// it is a regular file of plausible size whose checksum matches.
//
// Where: $CLRT_CACHE_DIR, else $XDG_CACHE_HOME/clrt, else $HOME/.cache/clrt; CLRT_CACHE_DIR set
// but empty turns it off. A file is named by a hash of everything the binary depends on (source,
// options, platform, device and driver) and holds a second, independent hash of the same, so a
// collision of names reads as a miss.
#pragma once

#include <filesystem>
#include <optional>
#include <string>

namespace clrt {

class ProgramCache {
 public:
  // The folder from the environment, or none when caching is off or there is no home.
  static std::optional<std::filesystem::path> folder_from_environment();
  // Whether CLRT_CACHE_DIR names the folder: then every entry is stored by the build that misses
  // it, in the foreground, whatever the driver.
  static bool named_by_environment();

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

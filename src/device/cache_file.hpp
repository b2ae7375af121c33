// The files of clrt's caches (program entries, background store requests): read only when they
// are regular files of plausible size, written whole or not at all.
#pragma once

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>

namespace clrt {

// The bytes of `path` when it is a regular file of at most `largest` bytes. Opened without
// blocking, so that a FIFO put under the name cannot stall clrt.
std::optional<std::string> read_cache_file(const std::filesystem::path& path, std::uintmax_t largest);

// Writes `bytes` to a temporary beside `path` (its folder made if missing), flushes it to disk
// and renames it into place, so that a crash leaves the old file or the whole new one; another
// process may write the same file at the same time. False, and nothing left, when any step fails.
bool write_cache_file(const std::filesystem::path& path, const std::string& bytes);

}  // namespace clrt

// Program binaries made after the render, in a process of their own. Asked for a program's
// binary, PoCL compiles every kernel once more for any work-group size: seconds that a first
// render would wait for (docs/performance.md#start-up). Yet a warm run that loads the binary
// spares PoCL's lookup of the source in its own cache, about a fifth of a warm run. So for a
// driver that keeps its compiled kernels, a program built from source is only noted here; once
// the image is written, clrt starts itself again, detached and at low priority, to build the
// binary and store it in the program cache (program_cache.hpp) for the runs after.
#pragma once

#include <filesystem>
#include <string>

#include "device/opencl.hpp"

namespace clrt {

// Notes that the program of `source` built with `options` on `device` belongs in the cache entry
// `entry` (ProgramCache::file()), to be stored by start_background_stores().
void defer_program_store(const std::filesystem::path& entry, const compute::device& device,
                         const std::string& options, const std::string& source);

// For each program noted, unless a store of it is already under way (a request younger than ten
// minutes): writes a request beside its entry and starts `clrt --internal-store-program REQUEST`
// in a session of its own, its standard streams on /dev/null. Best effort, and silent: the cache
// is an optimisation only.
void start_background_stores();

// The background process: builds the program a request names on the device it names, stores
// its binary, and removes the request. 0 when stored, 1 otherwise (nobody reads it).
int store_program_from_request(const std::filesystem::path& request);

// The argument that makes clrt such a process.
constexpr const char* kStoreProgramArgument = "--internal-store-program";

}  // namespace clrt

// What a scene costs in memory, known while it loads: the loaders stop at the line where the
// estimate passes the memory this process may still take (memory_limit.hpp), before spending it.
#pragma once

#include <cstdint>
#include <string>

#include "scene/memory_limit.hpp"
#include "scene/scene.hpp"
#include "scene/source_location.hpp"

namespace clrt {

// Estimated bytes the scene's geometry tables take on a device (BVH nodes and leaf packets,
// instances, normals), built on the host first: measured 165 to 220 bytes per triangle or
// instance (docs/performance.md, BVH scaling); 256 are assumed. With the environment's table.
std::uint64_t estimated_geometry_bytes(const Scene& scene);

// The environment's table on a device: its radiance and a cumulative share, 16 bytes a pixel,
// and the rows' shares, four to 16 bytes.
std::uint64_t environment_table_bytes(std::int64_t width, std::int64_t height);
// What an environment map takes on the host from its load to its render: its radiance (12 bytes a
// pixel), and its table twice, as it is built and then packed with the lights for the device.
std::uint64_t environment_host_bytes(std::int64_t width, std::int64_t height);

// Estimated bytes the scene needs from its load to its render: its tables (the vectors counted
// twice, as a growing vector is copied into one twice its size; the instances' deque once), its
// environment and texture images, and its geometry tables.
std::uint64_t estimated_scene_bytes(const Scene& scene);

// Throws SceneError at `where`, loading stopped there, when `needed` bytes exceed `limit`.
void check_scene_memory(std::uint64_t needed, const MemoryLimit& limit, const SourceLocation& where);

}  // namespace clrt

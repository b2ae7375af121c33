// Writes built trees into the device's BVH table (kernels/shared/bvh.h), and reads records
// back out of it for the tests and tools.
#pragma once

#include <cstdint>
#include <optional>
#include <vector>

#include "geometry/bvh_builder.hpp"
#include "geometry/device_tables.hpp"
#include "geometry/instance_bounds.hpp"
#include "geometry/mesh_table.hpp"
#include "shared/bvh.h"
#include "shared/scene.h"

namespace clrt {

// What one of the top level's leaf items is: a sphere tested in world space, a mesh instance,
// or neither (a canonical shape, which the device tests through its instance record).
struct TopLevelItem {
  std::optional<WorldSphere> sphere;
  std::int64_t mesh_root = -1;  // a mesh instance: the block of its mesh's bottom-level root
  // A mesh instance that places its mesh, and is the only one to, with the identity transform:
  // the top level then leads straight into the mesh's nodes.
  bool merged = false;
  dev::f4 world_to_object[3] = {};  // a mesh instance's rows of M^-1
  dev::u32 motion = CLRT_NO_MOTION;  // a moving mesh instance's Instance.motion
};

// The top level's leaf items: item i is instance first_instance + i.
struct TopLevelItems {
  std::uint32_t first_instance = 0;
  std::vector<TopLevelItem> items;
};

// The slots the top level takes at the start of the table: its nodes and its leaves' packets.
std::size_t top_level_slots(const BvhTree& tree, const TopLevelItems& items);

// Writes the top level into the table's first top_level_slots() slots, which must exist.
void write_top_level(const BvhTree& tree, const TopLevelItems& items, BvhTable& table);

// Appends a mesh's bottom level, built over the triangles of `source` (leaf item i is its
// triangle tree.order[i], row first_triangle + i of the per-triangle tables): its nodes, then its
// leaves' triangle packets, written on every core, which name `only_instance` (see
// BvhTrianglePacket). Returns the block of its root.
std::uint32_t append_mesh_level(const BvhTree& tree, const TriangleSource& source, std::uint32_t first_triangle,
                                std::uint32_t only_instance, BvhTable& table);

// The records that start at `block`.
dev::BvhNode node_at(const BvhTable& table, std::uint32_t block);
dev::BvhTrianglePacket triangle_packet_at(const BvhTable& table, std::uint32_t block);
dev::BvhSpherePacket sphere_packet_at(const BvhTable& table, std::uint32_t block);
dev::BvhMeshInstancePacket mesh_instance_packet_at(const BvhTable& table, std::uint32_t block);

}  // namespace clrt

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

// A sphere tested in world space as its leaf packet holds it (BvhSpherePacket), in single
// precision: 16 bytes for each of the top level's items rather than 40 (3M spheres: 72 MB).
struct SphereLane {
  float center[3] = {0, 0, 0};
  float radius = -1;  // negative: the item is no such sphere

  explicit operator bool() const { return radius >= 0; }
  static SphereLane of(const std::optional<WorldSphere>& sphere);
};

// The top level's leaf items, item i being instance first_instance + i of the instance table
// (already in leaf order): a sphere tested in world space, a mesh instance, or neither (a
// canonical shape, which the device tests through its instance record). Nothing is copied per
// item but the spheres: a scene of 3M spheres has 3M items.
struct TopLevelItems {
  std::uint32_t first_instance = 0;
  const dev::Instance* instances = nullptr;  // the instance table
  const dev::Mesh* meshes = nullptr;         // the mesh table; root_node read once it is set
  // Per mesh: the instance that places it alone with the identity transform, where the top level
  // then leads straight into the mesh's nodes (identity_only_instances); else CLRT_NO_HIT.
  std::vector<dev::u32> only;
  std::vector<SphereLane> spheres;  // per item

  std::size_t size() const { return spheres.size(); }
  const dev::Instance& instance(std::size_t item) const { return instances[first_instance + item]; }
  bool is_mesh(std::size_t item) const { return instance(item).shape == CLRT_SHAPE_MESH; }
  bool merged(std::size_t item) const {
    return is_mesh(item) && only[instance(item).mesh] == first_instance + item;
  }
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

// Structural checks of a BVH in the device table, walked on the host.
#pragma once

#include <functional>
#include <set>
#include <string>
#include <vector>

#include "math/vec3.hpp"
#include "geometry/device_tables.hpp"
#include "shared/bvh.h"

namespace clrt::bvhtest {

struct TreeShape {
  int depth = 0;      // node levels on the longest path
  int max_leaf = 0;   // most items in one leaf
  int nodes = 0;
  int leaves = 0;
  int lanes = 0;      // non-empty lanes
  std::vector<dev::BvhMeshInstancePacket> mesh_instances;  // the top level's, as found
};

// A top level's leaves hold one instance, one mesh instance's packet or packets of spheres; a
// mesh level's leaves hold triangle packets.
enum class Level { Top, Mesh };

// Walks the tree at block `root`, whose leaves must hold every item of [first, first + count)
// exactly once. `points(item)` lists points on the item, which its box must contain; for a mesh
// level they are the triangle's three vertices, which its packet lane must hold exactly (and
// its other lanes nothing); a sphere packet's lane must hold a sphere through all of them. At
// the top level, an inner lane that leads to a block of `mesh_roots` stands for the instance its
// mesh's packets name. Every lane box above an item must contain its points, and an empty lane
// must have an empty box. Problems are appended to `errors`.
TreeShape check_tree(const BvhTable& table, std::uint32_t root, Level level,
                     std::uint32_t first, std::uint32_t count,
                     const std::function<std::vector<Vec3>(std::uint32_t)>& points,
                     std::vector<std::string>& errors, const std::set<std::uint32_t>& mesh_roots = {});

// The instance that the packets of the mesh level at `root` name (CLRT_NO_HIT for none); every
// packet must name the same one.
std::uint32_t packets_instance(const BvhTable& table, std::uint32_t root,
                               std::vector<std::string>& errors);

}  // namespace clrt::bvhtest

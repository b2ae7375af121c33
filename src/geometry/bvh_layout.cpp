#include "geometry/bvh_layout.hpp"

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <stdexcept>
#include <string>

#include "math/parallel_for.hpp"
#include "shared/ray.h"

namespace clrt {
namespace {

constexpr std::size_t kBlock = sizeof(dev::BvhBlock);
constexpr std::size_t kSlotBlocks = CLRT_BVH_NODE_BLOCKS;  // a slot of the table is one node
constexpr std::uint32_t kPacket = CLRT_BVH_PACKET;

static_assert(sizeof(dev::BvhNode) == CLRT_BVH_NODE_BLOCKS * kBlock, "node blocks");
static_assert(sizeof(dev::BvhTrianglePacket) == CLRT_BVH_PACKET_BLOCKS * kBlock, "packet blocks");
static_assert(sizeof(dev::BvhSpherePacket) == CLRT_BVH_SPHERE_BLOCKS * kBlock, "packet blocks");
static_assert(sizeof(dev::BvhMeshInstancePacket) == CLRT_BVH_MESH_INSTANCE_BLOCKS * kBlock, "packet blocks");

std::uint32_t packets_for(std::uint32_t items) { return (items + kPacket - 1) / kPacket; }

std::size_t slots_for_blocks(std::size_t blocks) { return (blocks + kSlotBlocks - 1) / kSlotBlocks; }

std::uint32_t checked_block(std::size_t block) {
  if (block > static_cast<std::size_t>(INT32_MAX)) throw std::length_error("BVH: table too large");
  return static_cast<std::uint32_t>(block);
}

// The leaves of `tree` in item order (they cover the items in slices), found by their first
// items without a sort.
struct Leaves {
  std::vector<const BvhLane*> in_order;
  std::vector<std::uint32_t> index_at;  // of the leaf that starts at item i, in in_order

  explicit Leaves(const BvhTree& tree) : index_at(tree.order.size(), 0) {
    std::vector<const BvhLane*> starting_at(tree.order.size(), nullptr);
    std::size_t count = 0;
    for (const BvhTreeNode& node : tree.nodes)
      for (const BvhLane& lane : node.lane)
        if (lane.leaf()) {
          starting_at.at(lane.first) = &lane;
          ++count;
        }
    // Sized exactly: these tables live while the BVH table, the build's largest, is written.
    in_order.reserve(count);
    for (const BvhLane* leaf : starting_at)
      if (leaf) {
        index_at[leaf->first] = static_cast<std::uint32_t>(in_order.size());
        in_order.push_back(leaf);
      }
  }

  std::uint32_t index(const BvhLane& leaf) const { return index_at[leaf.first]; }
};

// A leaf's reference and count, as BvhNode stores them.
struct LeafRef {
  dev::i32 child;
  dev::u32 count;
};

// Writes the tree's nodes from slot `first_slot` of `table`; `leaf_ref(lane)` gives a leaf lane's
// reference. Returns the root's block.
template <class LeafRefOf>
std::uint32_t write_nodes(const BvhTree& tree, std::size_t first_slot, BvhTable& table,
                          LeafRefOf leaf_ref) {
  const std::uint32_t root = checked_block(first_slot * kSlotBlocks);
  checked_block((first_slot + tree.nodes.size()) * kSlotBlocks);
  for (std::size_t n = 0; n < tree.nodes.size(); ++n) {
    dev::BvhNode& out = table.at(first_slot + n);
    for (int k = 0; k < CLRT_BVH_WIDTH; ++k) {
      const BvhLane& lane = tree.nodes[n].lane[k];
      out.min_x.lane[k] = lane.box.lo[0];
      out.min_y.lane[k] = lane.box.lo[1];
      out.min_z.lane[k] = lane.box.lo[2];
      out.max_x.lane[k] = lane.box.hi[0];
      out.max_y.lane[k] = lane.box.hi[1];
      out.max_z.lane[k] = lane.box.hi[2];
      out.child[k] = CLRT_BVH_EMPTY_LANE;
      out.count[k] = 0;
      if (lane.node >= 0) {
        out.child[k] = static_cast<dev::i32>(root + static_cast<std::uint32_t>(lane.node) * kSlotBlocks);
      } else if (lane.leaf()) {
        const LeafRef ref = leaf_ref(lane);
        out.child[k] = ref.child;
        out.count[k] = ref.count;
      }
    }
  }
  return root;
}

// Writes packet p (whole blocks) at block `block`, within the table.
template <class Packet>
void write_packet(BvhTable& table, std::size_t block, const Packet& p) {
  if ((block * kBlock + sizeof p) > table.size() * sizeof(dev::BvhNode))
    throw std::logic_error("BVH: packet outside the table");
  std::memcpy(reinterpret_cast<unsigned char*>(table.data()) + block * kBlock, &p, sizeof p);
}

template <class Packet>
Packet read_packet(const BvhTable& table, std::uint32_t block) {
  if ((static_cast<std::size_t>(block) * kBlock + sizeof(Packet)) > table.size() * sizeof(dev::BvhNode))
    throw std::out_of_range("BVH: no packet at block " + std::to_string(block));
  Packet p;
  std::memcpy(&p, reinterpret_cast<const unsigned char*>(table.data()) + block * kBlock, sizeof p);
  return p;
}

void set_lane(dev::f4& v, std::uint32_t lane, float value) { (&v.x)[lane] = value; }

// The packet of leaf items [first, first + count) of a mesh's tree.
dev::BvhTrianglePacket triangle_packet(const BvhTree& tree, const TriangleSource& source, std::uint32_t first,
                                       std::uint32_t count, std::uint32_t first_triangle, std::uint32_t only_instance) {
  dev::BvhTrianglePacket p{};
  p.instance = only_instance;
  for (std::uint32_t k = 0; k < kPacket; ++k) {
    p.triangle[k] = k < count ? first_triangle + first + k : CLRT_NO_HIT;
    if (k >= count) continue;
    const dev::Triangle t = source.triangle(tree.order[first + k]);
    const dev::f4* vertex[3] = {&t.v0, &t.v1, &t.v2};
    for (int j = 0; j < 3; ++j) {
      set_lane(p.v[3 * j + 0], k, vertex[j]->x);
      set_lane(p.v[3 * j + 1], k, vertex[j]->y);
      set_lane(p.v[3 * j + 2], k, vertex[j]->z);
    }
  }
  return p;
}

dev::BvhSpherePacket sphere_packet(const TopLevelItems& top, std::uint32_t first, std::uint32_t count) {
  dev::BvhSpherePacket p{};
  for (std::uint32_t k = 0; k < kPacket; ++k) {
    p.instance[k] = k < count ? top.first_instance + first + k : CLRT_NO_HIT;
    if (k >= count) continue;
    const SphereLane& s = top.spheres.at(first + k);
    set_lane(p.center_x, k, s.center[0]);
    set_lane(p.center_y, k, s.center[1]);
    set_lane(p.center_z, k, s.center[2]);
    set_lane(p.radius, k, s.radius);
  }
  return p;
}

dev::BvhMeshInstancePacket mesh_instance_packet(const TopLevelItems& top, std::uint32_t item) {
  const dev::Instance& inst = top.instance(item);
  dev::BvhMeshInstancePacket p{};
  for (int r = 0; r < 3; ++r) p.world_to_object[r] = inst.world_to_object[r];
  p.root = top.meshes[inst.mesh].root_node;
  p.instance = top.first_instance + item;
  p.motion = inst.motion;
  return p;
}

// The blocks of packets a top-level leaf needs.
std::size_t packet_blocks(const TopLevelItems& top, const BvhLane& leaf) {
  if (top.spheres.at(leaf.first)) return packets_for(leaf.count) * std::size_t{CLRT_BVH_SPHERE_BLOCKS};
  return top.is_mesh(leaf.first) && !top.merged(leaf.first) ? CLRT_BVH_MESH_INSTANCE_BLOCKS : 0;
}

// Writes the packets of a top-level leaf from `block` on; returns its reference.
LeafRef write_top_leaf(const TopLevelItems& top, const BvhLane& leaf, std::size_t block,
                       BvhTable& table) {
  const auto ref = ~static_cast<dev::i32>(checked_block(block));
  if (top.spheres.at(leaf.first)) {
    for (std::uint32_t done = 0; done < leaf.count; done += kPacket, block += CLRT_BVH_SPHERE_BLOCKS)
      write_packet(table, block, sphere_packet(top, leaf.first + done, std::min(kPacket, leaf.count - done)));
    return {ref, CLRT_BVH_SPHERE_LEAF | packets_for(leaf.count)};
  }
  if (leaf.count != 1) throw std::logic_error("BVH: a top-level leaf of several instances that are not spheres");
  if (top.merged(leaf.first))
    return {static_cast<dev::i32>(top.meshes[top.instance(leaf.first).mesh].root_node), 0};
  if (top.is_mesh(leaf.first)) {
    write_packet(table, block, mesh_instance_packet(top, leaf.first));
    return {ref, CLRT_BVH_MESH_LEAF};
  }
  return {~static_cast<dev::i32>(top.first_instance + leaf.first), CLRT_BVH_INSTANCE_LEAF};
}

}  // namespace

SphereLane SphereLane::of(const std::optional<WorldSphere>& sphere) {
  if (!sphere) return {};
  return {{static_cast<float>(sphere->center.x), static_cast<float>(sphere->center.y),
           static_cast<float>(sphere->center.z)},
          static_cast<float>(sphere->radius)};
}

std::size_t top_level_slots(const BvhTree& tree, const TopLevelItems& top) {
  std::size_t blocks = 0;
  for (const BvhLane* leaf : Leaves(tree).in_order) blocks += packet_blocks(top, *leaf);
  return tree.nodes.size() + slots_for_blocks(blocks);
}

void write_top_level(const BvhTree& tree, const TopLevelItems& top, BvhTable& table) {
  const Leaves leaves(tree);
  std::size_t block = tree.nodes.size() * kSlotBlocks;  // the next packet's
  std::vector<LeafRef> refs;
  for (const BvhLane* leaf : leaves.in_order) {
    refs.push_back(write_top_leaf(top, *leaf, block, table));
    block += packet_blocks(top, *leaf);
  }
  write_nodes(tree, 0, table, [&](const BvhLane& lane) {
    return refs[leaves.index(lane)];
  });
}

std::uint32_t append_mesh_level(const BvhTree& tree, const TriangleSource& source, std::uint32_t first_triangle,
                                std::uint32_t only_instance, BvhTable& table) {
  const Leaves leaves(tree);
  const std::size_t first_slot = table.size();
  const std::size_t packets_block = (first_slot + tree.nodes.size()) * kSlotBlocks;
  std::vector<LeafRef> refs;
  refs.reserve(leaves.in_order.size());
  std::size_t block = packets_block;
  for (const BvhLane* leaf : leaves.in_order) {
    const std::uint32_t packets = packets_for(leaf->count);
    refs.push_back({~static_cast<dev::i32>(checked_block(block)), packets});
    block += packets * CLRT_BVH_PACKET_BLOCKS;
  }
  table.resize(first_slot + tree.nodes.size() + slots_for_blocks(block - packets_block));
  const std::uint32_t root = write_nodes(tree, first_slot, table, [&](const BvhLane& lane) {
    return refs[leaves.index(lane)];
  });
  parallel_for(leaves.in_order.size(), 8192, [&](std::size_t l) {
    const BvhLane& leaf = *leaves.in_order[l];
    std::size_t at = static_cast<std::size_t>(~refs[l].child);
    for (std::uint32_t done = 0; done < leaf.count; done += kPacket, at += CLRT_BVH_PACKET_BLOCKS)
      write_packet(table, at,
                   triangle_packet(tree, source, leaf.first + done, std::min(kPacket, leaf.count - done),
                                   first_triangle, only_instance));
  });
  return root;
}

dev::BvhNode node_at(const BvhTable& table, std::uint32_t block) {
  if (block % kSlotBlocks != 0 || block / kSlotBlocks >= table.size())
    throw std::out_of_range("BVH: no node at block " + std::to_string(block));
  return table[block / kSlotBlocks];
}

dev::BvhTrianglePacket triangle_packet_at(const BvhTable& table, std::uint32_t block) {
  return read_packet<dev::BvhTrianglePacket>(table, block);
}

dev::BvhSpherePacket sphere_packet_at(const BvhTable& table, std::uint32_t block) {
  return read_packet<dev::BvhSpherePacket>(table, block);
}

dev::BvhMeshInstancePacket mesh_instance_packet_at(const BvhTable& table, std::uint32_t block) {
  return read_packet<dev::BvhMeshInstancePacket>(table, block);
}

}  // namespace clrt

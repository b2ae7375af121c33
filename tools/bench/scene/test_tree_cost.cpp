// sah_cost on hand-made BVH tables, against the sum worked out by hand.
#include <catch2/catch.hpp>

#include "geometry/bvh_box.hpp"
#include "tree_cost.hpp"

namespace clrt::bench {
namespace {

constexpr std::uint32_t kNodeBlocks = CLRT_BVH_NODE_BLOCKS;

dev::BvhNode empty_node() {
  dev::BvhNode n{};
  for (int k = 0; k < CLRT_BVH_WIDTH; ++k) {
    n.min_x.lane[k] = n.min_y.lane[k] = n.min_z.lane[k] = Box::kInf;
    n.max_x.lane[k] = n.max_y.lane[k] = n.max_z.lane[k] = -Box::kInf;
    n.child[k] = CLRT_BVH_EMPTY_LANE;
  }
  return n;
}

void set_lane(dev::BvhNode& n, int k, Box b, dev::i32 child, dev::u32 count) {
  n.min_x.lane[k] = b.lo[0], n.max_x.lane[k] = b.hi[0];
  n.min_y.lane[k] = b.lo[1], n.max_y.lane[k] = b.hi[1];
  n.min_z.lane[k] = b.lo[2], n.max_z.lane[k] = b.hi[2];
  n.child[k] = child;
  n.count[k] = count;
}

Box box(float x0, float x1, float y0, float y1, float z0, float z1) {
  Box b;
  b.lo[0] = x0, b.hi[0] = x1, b.lo[1] = y0, b.hi[1] = y1, b.lo[2] = z0, b.hi[2] = z1;
  return b;
}

TEST_CASE("a root with two leaves costs the root plus each leaf's packets by its area share") {
  BvhTable table(1, empty_node());
  // Root box 3 x 1 x 1: half area 3 + 1 + 3 = 7; each leaf 1 x 1 x 1: half area 3.
  set_lane(table[0], 0, box(0, 1, 0, 1, 0, 1), -5, 1);
  set_lane(table[0], 3, box(2, 3, 0, 1, 0, 1), -9, 2);
  CHECK(sah_cost(table) == Approx(1.0 + 3.0 / 7.0 * 1 + 3.0 / 7.0 * 2));
  CHECK(sah_cost(table, 2.0) == Approx(2.0 + 3.0 / 7.0 * 3));
}

TEST_CASE("inner nodes cost a node visit by their share and their children are summed too") {
  BvhTable table(2, empty_node());
  // Root: an inner child over 2 x 2 x 2 (half area 12) and a sphere leaf of 3 packets over
  // 2 x 1 x 1 (half area 5); the root box 4 x 2 x 2 has half area 8 + 4 + 8 = 20.
  set_lane(table[0], 0, box(0, 2, 0, 2, 0, 2), static_cast<dev::i32>(kNodeBlocks), 0);
  set_lane(table[0], 1, box(2, 4, 0, 1, 0, 1), -20, CLRT_BVH_SPHERE_LEAF | 3u);
  // The inner node: an instance leaf over 1 x 1 x 1 and a mesh instance leaf over 2 x 2 x 2.
  set_lane(table[1], 0, box(0, 1, 0, 1, 0, 1), -30, CLRT_BVH_INSTANCE_LEAF);
  set_lane(table[1], 1, box(0, 2, 0, 2, 0, 2), -40, CLRT_BVH_MESH_LEAF);
  const double expected = 1.0 + 12.0 / 20 + 5.0 / 20 * 3 + 3.0 / 20 * 1 + 12.0 / 20 * 1;
  CHECK(sah_cost(table) == Approx(expected));
}

TEST_CASE("an empty table costs nothing and a flat root only its own visit") {
  CHECK(sah_cost(BvhTable{}) == 0.0);
  CHECK(sah_cost(BvhTable(1, empty_node())) == 1.0);
}

}  // namespace
}  // namespace clrt::bench

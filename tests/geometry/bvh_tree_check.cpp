#include "bvh_tree_check.hpp"

#include <algorithm>
#include <cmath>

#include "geometry/bvh_box.hpp"
#include "geometry/bvh_layout.hpp"
#include "shared/ray.h"

namespace clrt::bvhtest {
namespace {

constexpr std::uint32_t kNodeBlocks = sizeof(dev::BvhNode) / 64;

bool contains(const Box& box, const Vec3& p) {
  for (int a = 0; a < 3; ++a)
    if (p[a] < box.lo[a] || p[a] > box.hi[a]) return false;
  return true;
}

float packet_vertex(const dev::BvhTrianglePacket& p, int j, int axis, int lane) {
  return (&p.v[3 * j + axis].x)[lane];
}

class Walker {
 public:
  Walker(const BvhTable& table, Level level, std::uint32_t first, std::uint32_t count,
         const std::function<std::vector<Vec3>(std::uint32_t)>& points, std::vector<std::string>& errors,
         const std::set<std::uint32_t>& mesh_roots)
      : table_(table), level_(level), first_(first), seen_(count, 0), points_(points), errors_(errors),
        mesh_roots_(mesh_roots) {}

  // The top level may be a mesh's level itself, when it holds just that mesh.
  void root(std::uint32_t block) {
    if (level_ == Level::Top && mesh_roots_.count(block)) merged_mesh(block);
    else node(block, 1);
  }

  void node(std::uint32_t block, int depth) {
    shape_.depth = std::max(shape_.depth, depth);
    ++shape_.nodes;
    if (block % kNodeBlocks != 0 || block / kNodeBlocks >= table_.size())
      return fail("node block " + std::to_string(block) + " out of range");
    const dev::BvhNode& n = table_[block / kNodeBlocks];
    for (int k = 0; k < CLRT_BVH_WIDTH; ++k) {
      if (n.child[k] < 0 && n.count[k] == 0) {
        if (!lane_box(n, k).empty()) fail("an empty lane with a box that rays can enter");
        continue;
      }
      ++shape_.lanes;
      ancestors_.push_back(lane_box(n, k));
      if (n.child[k] >= 0) {
        const auto child = static_cast<std::uint32_t>(n.child[k]);
        if (child <= block) fail("inner lane points backwards (a cycle is possible)");
        else if (level_ == Level::Top && mesh_roots_.count(child)) merged_mesh(child);
        else node(child, depth + 1);
      } else {
        ++shape_.leaves;
        leaf(~static_cast<std::uint32_t>(n.child[k]), n.count[k]);
      }
      ancestors_.pop_back();
    }
  }

  TreeShape finish() {
    for (std::size_t i = 0; i < seen_.size(); ++i)
      if (seen_[i] != 1)
        fail("item " + std::to_string(first_ + i) + " is in " + std::to_string(seen_[i]) + " leaves");
    return shape_;
  }

 private:
  void leaf(std::uint32_t ref, std::uint32_t count) {
    if (level_ == Level::Top && count == CLRT_BVH_INSTANCE_LEAF) {
      shape_.max_leaf = std::max(shape_.max_leaf, 1);
      item(ref);
    } else if (level_ == Level::Top && count == CLRT_BVH_MESH_LEAF) {
      shape_.max_leaf = std::max(shape_.max_leaf, 1);
      shape_.mesh_instances.push_back(mesh_instance_packet_at(table_, ref));
      item(shape_.mesh_instances.back().instance);
    } else if (level_ == Level::Top && (count & CLRT_BVH_SPHERE_LEAF)) {
      sphere_leaf(ref, count & ~CLRT_BVH_SPHERE_LEAF);
    } else if (level_ == Level::Mesh && count > 0 && count * CLRT_BVH_PACKET <= CLRT_BVH_MAX_TRIANGLES) {
      triangle_leaf(ref, count);
    } else {
      fail("a leaf with count " + std::to_string(count));
    }
  }

  void merged_mesh(std::uint32_t root) {
    ++shape_.leaves;
    item(packets_instance(table_, root, errors_));
  }

  void sphere_leaf(std::uint32_t ref, std::uint32_t packets) {
    if (packets == 0 || packets * CLRT_BVH_PACKET > CLRT_BVH_MAX_SPHERES)
      return fail("a sphere leaf of " + std::to_string(packets) + " packets");
    int items = 0;
    for (std::uint32_t p = 0; p < packets; ++p) {
      const dev::BvhSpherePacket packet = sphere_packet_at(table_, ref + p * CLRT_BVH_SPHERE_BLOCKS);
      for (int lane = 0; lane < CLRT_BVH_PACKET; ++lane) {
        const float* c[4] = {&packet.center_x.x, &packet.center_y.x, &packet.center_z.x, &packet.radius.x};
        const std::uint32_t instance = packet.instance[lane];
        if (instance == CLRT_NO_HIT) {
          if (c[3][lane] != 0.0f) fail("an empty sphere lane with a radius");
          continue;
        }
        ++items;
        if (!item(instance)) continue;
        const Vec3 center{c[0][lane], c[1][lane], c[2][lane]};
        const double r = c[3][lane];
        for (const Vec3& point : points_(instance))
          if (std::abs(length(point - center) - r) > 1e-5 * (r + length(center)))
            fail("instance " + std::to_string(instance) + ": its world sphere misses its surface");
      }
    }
    check_packet_fill(items, packets);
  }

  void triangle_leaf(std::uint32_t ref, std::uint32_t packets) {
    int items = 0;
    for (std::uint32_t p = 0; p < packets; ++p) {
      const dev::BvhTrianglePacket packet = triangle_packet_at(table_, ref + p * CLRT_BVH_PACKET_BLOCKS);
      for (int lane = 0; lane < CLRT_BVH_PACKET; ++lane) {
        const std::uint32_t t = packet.triangle[lane];
        if (t == CLRT_NO_HIT) {
          for (int j = 0; j < 3; ++j)
            for (int a = 0; a < 3; ++a)
              if (packet_vertex(packet, j, a, lane) != 0.0f) fail("an empty packet lane with a vertex");
          continue;
        }
        ++items;
        if (item(t)) check_vertices(packet, lane, t);
      }
    }
    check_packet_fill(items, packets);
  }

  // A leaf's packets are full but for the last, which holds something.
  void check_packet_fill(int items, std::uint32_t packets) {
    if (items <= (static_cast<int>(packets) - 1) * CLRT_BVH_PACKET) fail("a leaf with an empty packet");
    shape_.max_leaf = std::max(shape_.max_leaf, items);
  }

  // Counts `t` as seen and checks its box; false when it is out of range.
  bool item(std::uint32_t t) {
    if (t < first_ || t - first_ >= seen_.size()) {
      fail("leaf item " + std::to_string(t) + " out of range");
      return false;
    }
    ++seen_[t - first_];
    for (const Vec3& p : points_(t))
      for (const Box& box : ancestors_)
        if (!contains(box, p)) fail("item " + std::to_string(t) + " sticks out of a lane box above it");
    return true;
  }

  void check_vertices(const dev::BvhTrianglePacket& packet, int lane, std::uint32_t t) {
    const std::vector<Vec3> vertices = points_(t);
    for (int j = 0; j < 3 && j < static_cast<int>(vertices.size()); ++j)
      for (int a = 0; a < 3; ++a)
        if (packet_vertex(packet, j, a, lane) != static_cast<float>(vertices[j][a]))
          fail("triangle " + std::to_string(t) + ": its packet lane holds other vertices");
  }

  void fail(const std::string& what) {
    if (errors_.size() < 20) errors_.push_back(what);
  }

  const BvhTable& table_;
  Level level_;
  std::uint32_t first_;
  std::vector<int> seen_;
  const std::function<std::vector<Vec3>(std::uint32_t)>& points_;
  std::vector<std::string>& errors_;
  const std::set<std::uint32_t>& mesh_roots_;
  std::vector<Box> ancestors_;  // the decoded lane boxes on the path to the current lane
  TreeShape shape_;
};

// The packets of the mesh level at `block`, in tree order.
void collect_packets(const BvhTable& table, std::uint32_t block,
                     std::vector<dev::BvhTrianglePacket>& out) {
  const dev::BvhNode n = node_at(table, block);
  for (int k = 0; k < CLRT_BVH_WIDTH; ++k) {
    if (n.child[k] >= 0) collect_packets(table, static_cast<std::uint32_t>(n.child[k]), out);
    else if (n.count[k] > 0 && n.count[k] * CLRT_BVH_PACKET <= CLRT_BVH_MAX_TRIANGLES)
      for (std::uint32_t p = 0; p < n.count[k]; ++p)
        out.push_back(
            triangle_packet_at(table, ~static_cast<std::uint32_t>(n.child[k]) + p * CLRT_BVH_PACKET_BLOCKS));
  }
}

}  // namespace

TreeShape check_tree(const BvhTable& table, std::uint32_t root, Level level,
                     std::uint32_t first, std::uint32_t count,
                     const std::function<std::vector<Vec3>(std::uint32_t)>& points,
                     std::vector<std::string>& errors, const std::set<std::uint32_t>& mesh_roots) {
  Walker walker(table, level, first, count, points, errors, mesh_roots);
  walker.root(root);
  return walker.finish();
}

std::uint32_t packets_instance(const BvhTable& table, std::uint32_t root,
                               std::vector<std::string>& errors) {
  std::vector<dev::BvhTrianglePacket> packets;
  collect_packets(table, root, packets);
  const std::uint32_t instance = packets.empty() ? CLRT_NO_HIT : packets.front().instance;
  for (const dev::BvhTrianglePacket& p : packets)
    if (p.instance != instance) errors.push_back("the packets of one mesh name different instances");
  return instance;
}

}  // namespace clrt::bvhtest

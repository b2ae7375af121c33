// The surface area heuristic's cost of a built BVH table, so that a build that is faster but
// traces slower shows in clrt-bench's tables next to its build time.
#pragma once

#include "geometry/device_tables.hpp"

namespace clrt::bench {

// The expected cost of one random ray through the top level's tree, in packet tests: every node
// costs `node_cost` and every leaf its number of packets (a mesh instance's or a canonical
// shape's leaf counts one; the meshes below are not entered), each weighted by the chance that
// a ray through the root's box enters it (its surface area over the root's). The builder's own
// measure (BvhBuildSettings, node_cost 1), summed over the finished tree.
double sah_cost(const BvhTable& table, double node_cost = 1.0);

}  // namespace clrt::bench

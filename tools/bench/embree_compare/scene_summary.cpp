#include "scene_summary.hpp"

#include <cstdio>
#include <set>
#include <vector>

namespace clrt::compare {

std::string short_count(double n) {
  char text[32];
  if (n < 10000)
    std::snprintf(text, sizeof text, "%.0f", n);
  else if (n < 1e6)
    std::snprintf(text, sizeof text, "%.3gk", n / 1e3);
  else
    std::snprintf(text, sizeof text, "%.3gM", n / 1e6);
  return text;
}

std::string primitive_label(const Scene& scene) {
  int spheres = 0, planes = 0, mesh_instances = 0;
  double placed_triangles = static_cast<double>(scene.triangles.size());
  std::set<int> meshes_used;
  for (const InstanceSpec& i : scene.instances) {
    spheres += i.shape == ShapeKind::Sphere;
    planes += i.shape == ShapeKind::Plane;
    if (i.shape != ShapeKind::Mesh) continue;
    ++mesh_instances;
    meshes_used.insert(i.mesh);
    placed_triangles +=
        static_cast<double>(scene.meshes[static_cast<std::size_t>(i.mesh)].corners.size() / 3);
  }
  double distinct_triangles = static_cast<double>(scene.triangles.size());
  for (int m : meshes_used)
    distinct_triangles +=
        static_cast<double>(scene.meshes[static_cast<std::size_t>(m)].corners.size() / 3);

  std::vector<std::string> parts;
  if (spheres) parts.push_back(short_count(spheres) + " spheres");
  if (distinct_triangles > 0) {
    std::string tris = short_count(distinct_triangles) + " tris";
    if (placed_triangles > distinct_triangles)
      tris += " x " + short_count(mesh_instances) + " inst (" + short_count(placed_triangles) + ")";
    parts.push_back(tris);
  }
  if (planes) parts.push_back(std::to_string(planes) + (planes == 1 ? " plane" : " planes"));
  std::string label;
  for (const std::string& p : parts) label += (label.empty() ? "" : ", ") + p;
  return label;
}

}  // namespace clrt::compare

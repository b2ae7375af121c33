#include "scene/mesh_loader.hpp"

#include <tiny_obj_loader.h>

#include <cerrno>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "scene/obj_index_check.hpp"

namespace clrt {
namespace {

std::string read_mesh_file(const std::string& path) {
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec))
    throw MeshError(path + ": cannot be read (it is a folder)");
  std::ifstream in(path, std::ios::binary);
  if (!in) throw MeshError(path + ": cannot be read (" + std::strerror(errno) + ")");
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

std::string without_trailing_newlines(std::string s) {
  while (!s.empty() && (s.back() == '\n' || s.back() == '\r')) s.pop_back();
  return s;
}

std::vector<Vec3> to_points(const std::vector<tinyobj::real_t>& xyz, const std::string& path,
                            const char* what) {
  std::vector<Vec3> points;
  for (std::size_t i = 0; i + 2 < xyz.size(); i += 3) {
    const Vec3 p{xyz[i], xyz[i + 1], xyz[i + 2]};
    if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z))
      throw MeshError(path + ": " + what + " " + std::to_string(i / 3 + 1) + " is not finite");
    points.push_back(p);
  }
  return points;
}

}  // namespace

MeshData load_obj_mesh(const std::string& path) {
  const std::string text = read_mesh_file(path);
  check_obj_face_indices(text, path);

  tinyobj::attrib_t attrib;
  std::vector<tinyobj::shape_t> shapes;
  std::vector<tinyobj::material_t> materials;
  std::string warnings, errors;
  std::istringstream in(text);
  // No material reader: clrt takes the scene's current material, so `mtllib` is ignored.
  if (!tinyobj::LoadObj(&attrib, &shapes, &materials, &warnings, &errors, &in, nullptr, true))
    throw MeshError(path + ": " + without_trailing_newlines(errors));

  MeshData mesh;
  mesh.path = path;
  mesh.positions = to_points(attrib.vertices, path, "vertex");
  bool every_corner_has_normal = true;
  for (const tinyobj::shape_t& shape : shapes)
    for (const tinyobj::index_t& corner : shape.mesh.indices) {
      mesh.corners.push_back(static_cast<std::uint32_t>(corner.vertex_index));
      every_corner_has_normal = every_corner_has_normal && corner.normal_index >= 0;
      mesh.corner_normals.push_back(static_cast<std::uint32_t>(corner.normal_index));
    }
  if (mesh.corners.empty()) throw MeshError(path + ": the mesh has no triangles");
  if (every_corner_has_normal)
    mesh.normals = to_points(attrib.normals, path, "normal");
  else
    mesh.corner_normals.clear();
  return mesh;
}

}  // namespace clrt

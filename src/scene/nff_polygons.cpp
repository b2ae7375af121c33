// p and pp: polygons, and polygonal patches (polygons with a normal at each vertex).
#include <string>

#include "scene/nff_state.hpp"
#include "scene/polygon_triangulation.hpp"

namespace clrt {
namespace {

// The lexer holds every word of an entity: a larger polygon is refused before its vertices are
// read (a concave one above limits::kMaxConcavePolygonCorners once they are).
constexpr int kMaxPolygonVertices = 1 << 20;

// The vertex count, checked against the numbers that follow it (`per_vertex` for each vertex).
std::size_t vertex_count(const CommandArgs& a, std::size_t per_vertex, const std::string& layout) {
  if (a.count() == 0)
    throw a.error_past_end("wrong number of arguments: " + a.command_word().text +
                           " needs its vertex count");
  const auto n = static_cast<std::size_t>(a.whole_number(0, 3, kMaxPolygonVertices, "the vertex count"));
  a.require_count(
      {n * per_vertex}, 1,
      a.command_word().text + " with " + a.word(0).text + " vertices (" + layout + " each)");
  return n;
}

std::vector<TriangleCorners> cut(const CommandArgs& a, const std::vector<Vec3>& vertices) {
  try {
    return triangulate_polygon(vertices);
  } catch (const ConcavePolygonTooLarge& e) {
    throw a.error_at(0, e.what());
  }
}

// p n, then x y z for each vertex: loose triangles in world space, as `triangle` gives.
void polygon(NffState& s, const CommandArgs& a) {
  const std::size_t n = vertex_count(a, 3, "x y z");
  std::vector<Vec3> vertices;
  for (std::size_t i = 0; i < n; ++i) vertices.push_back(a.vec3(1 + 3 * i));
  for (const TriangleCorners& t : cut(a, vertices))
    s.loader.scene.triangles.push_back(
        {vertices[t[0]], vertices[t[1]], vertices[t[2]], s.loader.material});
}

// The mesh that holds the current material's patches, placed once by the identity.
MeshData& patch_mesh(NffState& s, const CommandArgs& a) {
  Scene& scene = s.loader.scene;
  const auto known = s.patch_mesh.find(s.loader.material);
  if (known != s.patch_mesh.end()) return scene.meshes[known->second];
  const int index = static_cast<int>(scene.meshes.size());
  s.patch_mesh[s.loader.material] = index;
  scene.meshes.push_back({});
  scene.meshes.back().path =
      scene.path + " (pp patches of material " + std::to_string(s.loader.material) + ")";
  add_instance(s.loader, a.command_location(), ShapeKind::Mesh, Mat4::identity()).mesh = index;
  return scene.meshes.back();
}

// pp n, then x y z nx ny nz for each vertex: triangles with vertex normals, which only a mesh
// carries, so each material's patches go into one mesh.
void patch(NffState& s, const CommandArgs& a) {
  const std::size_t n = vertex_count(a, 6, "x y z nx ny nz");
  std::vector<Vec3> vertices, normals;
  for (std::size_t i = 0; i < n; ++i) {
    vertices.push_back(a.vec3(1 + 6 * i));
    normals.push_back(a.nonzero_vec3(4 + 6 * i, "a vertex normal"));
  }
  const std::vector<TriangleCorners> triangles = cut(a, vertices);
  if (triangles.empty()) return;
  MeshData& mesh = patch_mesh(s, a);
  const auto first = static_cast<std::uint32_t>(mesh.positions.size());
  mesh.positions.insert(mesh.positions.end(), vertices.begin(), vertices.end());
  mesh.normals.insert(mesh.normals.end(), normals.begin(), normals.end());
  for (const TriangleCorners& t : triangles)
    for (std::size_t corner : t) {
      mesh.corners.push_back(first + static_cast<std::uint32_t>(corner));
      mesh.corner_normals.push_back(first + static_cast<std::uint32_t>(corner));
    }
}

}  // namespace

void add_nff_polygon_entities(NffTable& table) {
  table["p"] = polygon;
  table["pp"] = patch;
}

}  // namespace clrt

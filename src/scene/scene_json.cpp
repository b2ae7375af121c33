#include "scene/scene_json.hpp"

#include <nlohmann/json.hpp>

#include "scene/light_kinds.hpp"

namespace clrt {
namespace {

// Keys in the order docs/scene-json.md lists them.
using Json = nlohmann::ordered_json;
using Writer = std::function<void(const std::string&)>;

Json matrix(const Mat4& m) {
  Json rows = Json::array();
  for (const auto& row : m.m) rows.push_back(Json::array({row[0], row[1], row[2], row[3]}));
  return rows;
}

const char* shape_name(ShapeKind shape) {
  switch (shape) {
    case ShapeKind::Sphere: return "sphere";
    case ShapeKind::Plane: return "plane";
    case ShapeKind::Cube: return "cube";
    case ShapeKind::Cylinder: return "cylinder";
    case ShapeKind::Cone: return "cone";
    case ShapeKind::Mesh: return "mesh";
  }
  return "?";
}

Json camera(const Scene& scene) {
  return {{"eye", json_of(scene.camera.eye)},
          {"lookat", json_of(scene.camera.lookat)},
          {"up", json_of(scene.camera.up)},
          {"fov_degrees", scene.camera.fov_degrees},
          {"aspect", static_cast<double>(scene.width) / scene.height},
          {"lens_radius", scene.camera.lens_radius},
          {"focus_distance", scene.camera.focus_distance},
          {"shutter", Json::array({scene.camera.shutter_open, scene.camera.shutter_close})}};
}

// Only the textured slots, so that a reader sees at a glance which terms vary over a surface.
Json material_textures(const MaterialSpec& m) {
  static const char* const slots[] = {"color", "ks", "kr", "kt"};
  Json j = Json::object();
  for (std::size_t slot = 0; slot < m.textures.size(); ++slot)
    if (m.textures[slot] >= 0) j[slots[slot]] = m.textures[slot];
  return j;
}

Json material(const MaterialSpec& m) {
  return {{"color", json_of(m.color)}, {"ka", m.ka}, {"kd", m.kd}, {"ks", m.ks},
          {"shininess", m.shininess}, {"kr", m.kr}, {"kt", m.kt}, {"ior", m.ior},
          {"emission", json_of(m.emission)}, {"textures", material_textures(m)}};
}

const char* texture_kind_name(TextureSpec::Kind kind) {
  switch (kind) {
    case TextureSpec::Kind::Image: return "image";
    case TextureSpec::Kind::Checker: return "checker";
    case TextureSpec::Kind::Noise: return "noise";
  }
  return "?";
}

// The image inline rather than as an index into a table of its own: a reader wants the file,
// and clrt reads a file shown by several textures once anyway.
Json texture(const Scene& scene, const TextureSpec& t) {
  Json j = {{"kind", texture_kind_name(t.kind)}};
  if (t.kind == TextureSpec::Kind::Image) {
    const TextureImage& image = scene.texture_images[static_cast<std::size_t>(t.image)];
    j["file"] = image.path;
    j["width"] = image.width;
    j["height"] = image.height;
    j["linear"] = image.linear;
    j["wrap"] = t.clamp ? "clamp" : "repeat";
  } else {
    j["colors"] = Json::array({json_of(t.color0), json_of(t.color1)});
  }
  if (t.kind == TextureSpec::Kind::Noise) j["octaves"] = t.octaves;
  j["scale"] = Json::array({t.scale[0], t.scale[1]});
  j["offset"] = Json::array({t.offset[0], t.offset[1]});
  return j;
}

Json light(const LightSpec& l) {
  Json j = {{"kind", l.kind}, {"color", json_of(l.color)}};
  light_kind(l.kind).dump(l, j);
  return j;
}

Json object(const Scene& scene, const InstanceSpec& o) {
  Json j = {{"shape", shape_name(o.shape)}, {"material", o.material}};
  if (o.shape == ShapeKind::Cone) j["radii"] = Json::array({o.cone_r0, o.cone_r1});
  if (o.shape == ShapeKind::Mesh) {
    j["mesh"] = o.mesh;
    j["mtl"] = o.mesh_materials;
  }
  j["transform"] = matrix(o.transform);
  if (o.motion >= 0) j["end_transform"] = matrix(scene.end_transforms[static_cast<std::size_t>(o.motion)]);
  j["line"] = o.place.line;
  j["column"] = o.place.column;
  return j;
}

Json uv_pair(float u, float v) { return Json::array({u, v}); }

Json triangle(const TriangleSpec& t) {
  Json j = {{"corners", Json::array({json_of(t.v0), json_of(t.v1), json_of(t.v2)})},
            {"material", t.material}};
  if (t.has_uv)
    j["uv"] = Json::array({uv_pair(t.uv[0], t.uv[1]), uv_pair(t.uv[2], t.uv[3]), uv_pair(t.uv[4], t.uv[5])});
  return j;
}

Json index_triple(const std::vector<std::uint32_t>& indices, std::size_t triangle) {
  return Json::array({indices[3 * triangle], indices[3 * triangle + 1], indices[3 * triangle + 2]});
}

// `[` element, element... `]`, each element converted as it is written; `separator` goes
// between them.
template <typename ElementAt>
void write_array(const Writer& write, std::size_t count, ElementAt element_at,
                 const std::string& separator) {
  write("[");
  for (std::size_t i = 0; i < count; ++i) {
    if (i) write(separator);
    write(element_at(i).dump());
  }
  write("]");
}

void write_mesh(const Writer& write, const MeshData& mesh) {
  const auto vec_at = [](const std::vector<Vec3>& table) {
    return [&table](std::size_t i) { return json_of(table[i]); };
  };
  const auto triples_of = [](const std::vector<std::uint32_t>& indices) {
    return [&indices](std::size_t i) { return index_triple(indices, i); };
  };
  write("{\"path\":" + Json(mesh.path).dump() + ",\"positions\":");
  write_array(write, mesh.positions.size(), vec_at(mesh.positions), ",");
  write(",\"triangles\":");
  write_array(write, mesh.corners.size() / 3, triples_of(mesh.corners), ",");
  write(",\"normals\":");
  write_array(write, mesh.normals.size(), vec_at(mesh.normals), ",");
  write(",\"triangle_normals\":");
  write_array(write, mesh.corner_normals.size() / 3, triples_of(mesh.corner_normals), ",");
  write(",\"texcoords\":");
  write_array(write, mesh.texcoords.size(), [&mesh](std::size_t i) {
    return uv_pair(mesh.texcoords[i][0], mesh.texcoords[i][1]);
  }, ",");
  write(",\"triangle_texcoords\":");
  write_array(write, mesh.corner_texcoords.size() / 3, [&mesh](std::size_t t) {
    const bool none = mesh.corner_texcoords[3 * t] == kNoMeshTexcoord;
    return none ? Json(nullptr) : index_triple(mesh.corner_texcoords, t);
  }, ",");
  write(",\"triangle_materials\":");
  write_array(write, mesh.triangle_names.size(), [&mesh](std::size_t t) {
    const std::uint32_t name = mesh.triangle_names[t];
    return Json(name == kNoMeshMaterial ? -1 : mesh.name_materials.at(name));
  }, ",");
  write("}");
}

Json environment(const Scene& scene) {
  if (!scene.environment) return nullptr;
  const EnvironmentSpec& env = *scene.environment;
  return {{"file", env.path}, {"scale", env.scale}, {"rotation", matrix(env.rotation)},
          {"width", env.width}, {"height", env.height}};
}

}  // namespace

Json json_of(const Vec3& v) { return Json::array({v.x, v.y, v.z}); }

void write_scene_json(const Scene& scene, const Writer& write) {
  // One key, and one element of each table, a line: a dump reads and compares line by line.
  const Json head = {{"format", "clrt-scene"},
                     {"version", kSceneJsonVersion},
                     {"scene", scene.path},
                     {"camera", camera(scene)},
                     {"resolution", Json::array({scene.width, scene.height})},
                     {"samples", scene.samples},
                     {"maxdepth", scene.max_depth},
                     {"background", json_of(scene.background)},
                     {"environment", environment(scene)}};
  write("{\n");
  for (const auto& [key, value] : head.items()) write(Json(key).dump() + ": " + value.dump() + ",\n");
  const std::string next = ",\n";
  write("\"materials\": ");
  write_array(write, scene.materials.size(), [&](std::size_t i) { return material(scene.materials[i]); }, next);
  write(",\n\"textures\": ");
  write_array(write, scene.textures.size(), [&](std::size_t i) { return texture(scene, scene.textures[i]); }, next);
  write(",\n\"lights\": ");
  write_array(write, scene.lights.size(), [&](std::size_t i) { return light(scene.lights[i]); }, next);
  write(",\n\"objects\": ");
  write_array(write, scene.instances.size(), [&](std::size_t i) { return object(scene, scene.instances[i]); }, next);
  write(",\n\"meshes\": [");
  for (std::size_t i = 0; i < scene.meshes.size(); ++i) {
    if (i) write(next);
    write_mesh(write, scene.meshes[i]);
  }
  write("],\n\"triangles\": ");
  write_array(write, scene.triangles.size(), [&](std::size_t i) { return triangle(scene.triangles[i]); }, next);
  write("\n}\n");
}

}  // namespace clrt

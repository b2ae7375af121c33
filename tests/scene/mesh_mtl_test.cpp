// OBJ files with MTL libraries: `usemtl` faces take the library's materials, mapped onto clrt's
// model as docs/scene-format.md#materials-from-mtl says; what cannot be used is a warning.
#include <catch2/catch.hpp>

#include <algorithm>

#include "scene/mesh_loader.hpp"
#include "scene/mtl_material.hpp"
#include "scene_test_support.hpp"

using clrt::load_scene;
using clrt::MaterialSpec;
using clrt::Scene;
using clrt::Vec3;
using clrt::test::load_error_of_file;
using clrt::test::ScratchDir;

namespace mesh_mtl_test {

// Three quads (six triangles): the first before any usemtl, then red, then glass.
const char* const kObj =
    "mtllib box.mtl\n"
    "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\n"
    "f 1 2 3 4\n"
    "usemtl red\n"
    "f 1 2 3 4\n"
    "usemtl glass\n"
    "f 1 2 3 4\n";

const char* const kMtl =
    "newmtl red\nKd 0.8 0.1 0.1\nKs 0.5 0.5 0.5\nNs 40\nillum 2\n"
    "newmtl glass\nKd 0 0 0\nKs 1 1 1\nNi 1.5\nd 0.1\nillum 7\n"
    "newmtl unused\nKd 0 0 1\n";

Scene load(const std::string& obj, const std::string& mtl, const std::string& scene_text) {
  ScratchDir dir;
  dir.write("box.obj", obj);
  if (!mtl.empty()) dir.write("box.mtl", mtl);
  return load_scene(dir.write("scene.ray", scene_text));
}

bool mentions(const Scene& scene, const std::string& text) {
  return std::any_of(scene.warnings.begin(), scene.warnings.end(),
                     [&](const std::string& w) { return w.find(text) != std::string::npos; });
}

}  // namespace mesh_mtl_test

using namespace mesh_mtl_test;

TEST_CASE("usemtl faces take their MTL materials, the others the current material", "[scene][mesh][mtl]") {
  const Scene scene = load(kObj, kMtl, "material 0 1 0 0.2 0.8 0 1 0 0\nmesh box.obj\n");
  REQUIRE(scene.meshes.size() == 1);
  const clrt::MeshData& mesh = scene.meshes[0];
  REQUIRE(mesh.material_names.size() == 2);
  CHECK(mesh.material_names[0].name == "red");
  CHECK(mesh.material_names[0].where.line == 7);
  CHECK(mesh.material_names[0].where.column == 8);
  CHECK(mesh.triangle_names == std::vector<std::uint32_t>{clrt::kNoMeshMaterial, clrt::kNoMeshMaterial, 0, 0, 1, 1});
  // Only the names the file uses become scene materials, after the scene's own.
  REQUIRE(scene.materials.size() == 4);
  CHECK(mesh.name_materials == std::vector<int>{2, 3});
  const MaterialSpec& red = scene.materials[2];
  CHECK(red.color.x == Approx(0.8));
  CHECK(red.kd == 1);
  CHECK(red.ks == Approx(0.5));
  CHECK(red.shininess == 40);
  CHECK(red.kr == 0);
  const MaterialSpec& glass = scene.materials[3];
  CHECK(glass.kr == 1);
  CHECK(glass.kt == Approx(0.9));
  CHECK(glass.ior == Approx(1.5));
  REQUIRE(scene.instances.size() == 1);
  CHECK(scene.instances[0].mesh_materials);
  CHECK(scene.instances[0].material == 1);
  CHECK(scene.warnings.empty());
}

TEST_CASE("mtl off gives every face the current material, and the mesh keeps its names for mtl on",
          "[scene][mesh][mtl]") {
  const Scene scene = load(kObj, kMtl, "mtl off\nmesh box.obj\nmtl ON\nmesh box.obj\n");
  REQUIRE(scene.instances.size() == 2);
  CHECK_FALSE(scene.instances[0].mesh_materials);
  CHECK(scene.instances[1].mesh_materials);
  CHECK(scene.instances[0].mesh == scene.instances[1].mesh);
}

TEST_CASE("mtl takes on or off", "[scene][mesh][mtl][errors]") {
  ScratchDir dir;
  const clrt::SceneError e = load_error_of_file(dir.write("scene.ray", "\nmtl maybe\n"));
  CHECK(e.where().line == 2);
  CHECK(e.where().column == 5);
  CHECK_THAT(e.message(), Catch::Contains("on or off"));
  CHECK_THAT(clrt::test::load_error("mtl of\n").message(), Catch::EndsWith("found 'of' (did you mean 'off'?)"));
  CHECK(clrt::test::load_error("mtl maybe\n").message().find("did you mean") == std::string::npos);
}

TEST_CASE("a missing library and an undefined name are warnings at their OBJ lines, and those faces "
          "take the current material",
          "[scene][mesh][mtl]") {
  const Scene scene = load(kObj, "", "mesh box.obj\n");
  CHECK(scene.meshes[0].name_materials == std::vector<int>{-1, -1});
  CHECK(scene.materials.size() == 1);
  CHECK(mentions(scene, "box.obj:1:8: warning: material library"));
  CHECK(mentions(scene, "box.obj:7:8: warning: material 'red' is in no material library"));
  CHECK(mentions(scene, "box.obj:9:8: warning: material 'glass' is in no material library"));
  CHECK(scene.warnings.size() == 3);
}

TEST_CASE("a malformed library is an error at the mesh command naming the material library and its line",
          "[scene][mesh][mtl][errors]") {
  ScratchDir dir;
  dir.write("box.obj", kObj);
  dir.write("box.mtl", "newmtl red\nKd 0.8 x 0.1\n");
  const clrt::SceneError e = load_error_of_file(dir.write("scene.ray", "\n mesh box.obj\n"));
  CHECK(e.where().line == 2);
  CHECK(e.where().column == 2);
  CHECK_THAT(e.message(), Catch::StartsWith("bad material library ") && Catch::Contains("box.mtl:2:"));
}

TEST_CASE("usemtl and mtllib need a name", "[scene][mesh][mtl][errors]") {
  for (const char* keyword : {"usemtl", "mtllib"}) {
    ScratchDir dir;
    dir.write("m.obj", std::string("v 0 0 0\nv 1 0 0\nv 0 1 0\n") + keyword + "   # none\nf 1 2 3\n");
    const clrt::SceneError e = load_error_of_file(dir.write("scene.ray", "mesh m.obj\n"));
    CHECK_THAT(e.message(), Catch::Contains("m.obj:4:" + std::to_string(std::string(keyword).size() + 1)));
  }
}

TEST_CASE("a usemtl in force carries across the slices of a large file", "[scene][mesh][mtl]") {
  // Over a MiB of faces, so the file is parsed in several slices; the names switch every 5000
  // faces.
  std::string obj = "v 0 0 0\nv 1 0 0\nv 0 1 0\n";
  const int faces = 120000;
  for (int f = 0; f < faces; ++f) {
    if (f % 5000 == 0) obj += "usemtl m" + std::to_string(f / 5000 % 3) + "\n";
    obj += "f 1 2 3\n";
  }
  ScratchDir dir;
  dir.write("big.obj", obj);
  const clrt::MeshData mesh = clrt::load_obj_mesh(dir.file("big.obj"));
  REQUIRE(mesh.triangle_names.size() == static_cast<std::size_t>(faces));
  REQUIRE(mesh.material_names.size() == 3);
  for (int f = 0; f < faces; ++f) {
    INFO("face " << f);
    REQUIRE(mesh.material_names[mesh.triangle_names[f]].name == "m" + std::to_string(f / 5000 % 3));
  }
}

TEST_CASE("an OBJ naming a material per face finds each in its library", "[scene][mesh][mtl]") {
  // 200000 materials: looked up one by one among all of them, this took minutes.
  const int count = 200000;
  std::string mtl, obj = "mtllib box.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\n";
  for (int i = count - 1; i >= 0; --i) mtl += "newmtl m" + std::to_string(i) + "\nKd " + std::to_string(i) + " 0 0\n";
  for (int i = 0; i < count; ++i) obj += "usemtl m" + std::to_string(i) + "\nf 1 2 3\n";
  const Scene scene = load(obj, mtl, "mesh box.obj\n");
  REQUIRE(scene.meshes.size() == 1);
  const clrt::MeshData& mesh = scene.meshes[0];
  REQUIRE(mesh.triangle_names.size() == static_cast<std::size_t>(count));
  REQUIRE(mesh.name_materials.size() == static_cast<std::size_t>(count));
  for (int i = 0; i < count; ++i) {
    INFO("face " << i);
    const int m = mesh.name_materials.at(mesh.triangle_names[i]);
    REQUIRE(m >= 0);
    REQUIRE(scene.materials.at(static_cast<std::size_t>(m)).color.x == i);
  }
  CHECK(scene.warnings.empty());
}

TEST_CASE("an MTL material maps onto clrt's model by the documented table", "[scene][mtl]") {
  std::vector<std::string> warnings;
  clrt::MtlMaterial plain;
  plain.name = "plain";
  const MaterialSpec none = clrt::material_from_mtl(plain, warnings);
  CHECK(none.color.x == 1);
  CHECK(none.kd == Approx(0.8));
  CHECK(none.ka == Approx(0.2));
  CHECK(none.ks == 0);

  clrt::MtlMaterial matte = plain;
  matte.ks = Vec3{0.7, 0.7, 0.7};
  matte.illum = 1;  // no highlight
  CHECK(clrt::material_from_mtl(matte, warnings).ks == 0);

  clrt::MtlMaterial mirror = plain;
  mirror.ks = Vec3{0.3, 0.6, 2.0};  // the largest channel, at most 1
  mirror.illum = 3;
  const MaterialSpec m = clrt::material_from_mtl(mirror, warnings);
  CHECK(m.ks == 1);
  CHECK(m.kr == 1);
  REQUIRE(warnings.size() == 1);  // the coloured highlight
  CHECK_THAT(warnings[0], Catch::Contains("highlight is white"));

  clrt::MtlMaterial lamp = plain;
  lamp.ke = Vec3{4, 3, 2};
  lamp.dissolve = 0.25f;
  const MaterialSpec l = clrt::material_from_mtl(lamp, warnings);
  CHECK(l.emission.x == 4);
  CHECK(l.kt == Approx(0.75));
}

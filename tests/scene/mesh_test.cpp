#include <catch2/catch.hpp>

#include <array>

#include "scene_test_support.hpp"

using clrt::load_scene;
using clrt::ShapeKind;
using clrt::Vec3;
using clrt::test::load_error_of_file;
using clrt::test::ScratchDir;

namespace {

// A unit square in the xy plane as one quad, counter-clockwise seen from +z, normals +z.
const char* const kQuadWithNormals =
    "# quad\nv 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nvn 0 0 1\nf 1//1 2//1 3//1 4//1\n";

// Two triangles sharing an edge, no normals; relative indices on the second face.
const char* const kTwoTrianglesNoNormals =
    "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\nf 1 2 3\nf -3 -1 -2\n";

Vec3 face_normal(const clrt::MeshData& m, std::size_t t) {
  const Vec3 a = m.positions[m.corners[3 * t]], b = m.positions[m.corners[3 * t + 1]],
             c = m.positions[m.corners[3 * t + 2]];
  return cross(b - a, c - a);
}

// Writes `obj_text` to `obj_name` and `scene_text` to scene.ray beside it, and loads the scene.
clrt::Scene load_with_obj(const std::string& obj_name, const std::string& obj_text,
                          const std::string& scene_text) {
  ScratchDir dir;
  dir.write(obj_name, obj_text);
  return load_scene(dir.write("scene.ray", scene_text));
}

// Writes `obj_text` to m.obj, loads a scene whose line 2 is "  mesh m.obj", returns the error.
clrt::SceneError mesh_error(const std::string& obj_text) {
  ScratchDir dir;
  dir.write("m.obj", obj_text);
  return load_error_of_file(dir.write("scene.ray", "\n  mesh m.obj\n"));
}

}  // namespace

TEST_CASE("a mesh with vertex normals: polygons triangulated, normals kept", "[scene][mesh]") {
  const clrt::Scene s =
      load_with_obj("quad.obj", kQuadWithNormals, "material 1 0 0 .2 .8 0 1 0 0\nmesh quad.obj\n");
  REQUIRE(s.meshes.size() == 1);
  const clrt::MeshData& m = s.meshes[0];
  CHECK(m.positions.size() == 4);
  CHECK(m.positions[2] == Vec3{1, 1, 0});
  REQUIRE(m.corners.size() == 6);
  for (std::size_t t = 0; t < 2; ++t) {
    // Both triangles keep the quad's counter-clockwise order: area 0.5 facing +z.
    const Vec3 n = face_normal(m, t);
    CHECK(n.x == 0);
    CHECK(n.y == 0);
    CHECK(n.z == Approx(1.0));
  }
  REQUIRE(m.normals.size() == 1);
  CHECK(m.normals[0] == Vec3{0, 0, 1});
  CHECK(m.corner_normals == std::vector<std::uint32_t>(6, 0));
  REQUIRE(s.instances.size() == 1);
  CHECK(s.instances[0].shape == ShapeKind::Mesh);
  CHECK(s.instances[0].mesh == 0);
  CHECK(s.instances[0].material == 1);
}

TEST_CASE("a mesh without normals leaves normals and corner_normals empty", "[scene][mesh]") {
  const clrt::Scene s = load_with_obj("tris.obj", kTwoTrianglesNoNormals, "mesh tris.obj\n");
  const clrt::MeshData& m = s.meshes.at(0);
  CHECK(m.corners == std::vector<std::uint32_t>{0, 1, 2, 1, 3, 2});
  CHECK(m.normals.empty());
  CHECK(m.corner_normals.empty());
  CHECK(m.texcoords.empty());
  CHECK(m.corner_texcoords.empty());
}

TEST_CASE("a mesh with texture coordinates keeps them per corner, the quad's cut included",
          "[scene][mesh][texcoords]") {
  const clrt::Scene s = load_with_obj(
      "quad.obj", "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nvt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\nvn 0 0 1\n"
                  "f 1/1/1 2/2/1 3/3/1 4/4/1\n",
      "mesh quad.obj\n");
  const clrt::MeshData& m = s.meshes.at(0);
  CHECK(m.texcoords == std::vector<std::array<float, 2>>{{0, 0}, {1, 0}, {1, 1}, {0, 1}});
  CHECK(m.corners == std::vector<std::uint32_t>{0, 1, 3, 1, 2, 3});
  CHECK(m.corner_texcoords == m.corners);
  CHECK(m.corner_normals == std::vector<std::uint32_t>(6, 0));
}

TEST_CASE("normals are dropped unless every corner has one", "[scene][mesh]") {
  const clrt::Scene s = load_with_obj(
      "partial.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\nvn 0 0 1\nf 1//1 2//1 3//1\nf 2 4 3\n",
      "mesh partial.obj\n");
  CHECK(s.meshes.at(0).corners.size() == 6);
  CHECK(s.meshes.at(0).normals.empty());
  CHECK(s.meshes.at(0).corner_normals.empty());
}

TEST_CASE("one mesh file is loaded once and shared by every instance", "[scene][mesh]") {
  ScratchDir dir;
  dir.write("scenes/models/quad.obj", kQuadWithNormals);
  dir.write("scenes/models/tris.obj", kTwoTrianglesNoNormals);
  const clrt::Scene s = load_scene(dir.write(
      "scenes/many.ray",
      "mesh models/quad.obj\ntranslate 2 0 0\nmesh ./models/quad.obj\nmesh models/tris.obj\n"
      "reset\nmesh models/../models/quad.obj\n"));
  REQUIRE(s.meshes.size() == 2);
  CHECK(s.meshes[0].path == dir.file("scenes/models/quad.obj"));
  CHECK(s.meshes[1].path == dir.file("scenes/models/tris.obj"));
  REQUIRE(s.instances.size() == 4);
  CHECK(s.instances[0].mesh == 0);
  CHECK(s.instances[1].mesh == 0);
  CHECK(s.instances[2].mesh == 1);
  CHECK(s.instances[3].mesh == 0);
  CHECK(s.instances[1].transform.m[0][3] == 2);
  CHECK(s.instances[3].transform.m[0][3] == 0);
}

TEST_CASE("a quoted mesh path may contain spaces", "[scene][mesh]") {
  const clrt::Scene s = load_with_obj("my models/quad #1.obj", kQuadWithNormals,
                                      "mesh \"my models/quad #1.obj\" # quoted\n");
  CHECK(s.meshes.at(0).corners.size() == 6);
}

TEST_CASE("a missing mesh file is an error at the mesh command naming the file",
          "[scene][mesh][errors]") {
  ScratchDir dir;
  const clrt::SceneError e =
      load_error_of_file(dir.write("scene.ray", "sphere\n\tmesh gone.obj\n"));
  CHECK(e.where().line == 2);
  CHECK(e.where().column == 2);
  CHECK_THAT(e.message(), Catch::Contains(dir.file("gone.obj") + ": cannot be read"));
}

TEST_CASE("bad OBJ indices are errors at the mesh command naming the OBJ line and column",
          "[scene][mesh][errors]") {
  const std::string verts = "v 0 0 0\nv 1 0 0\nv 0 1 0\n";  // lines 1-3
  SECTION("position index past the end") {
    const clrt::SceneError e = mesh_error(verts + "f 1 2 3\nf 1 2 4\n");
    CHECK(e.where().line == 2);
    CHECK(e.where().column == 3);
    CHECK_THAT(e.message(),
               Catch::Contains("bad mesh file ") && Catch::Contains("m.obj:5:7: vertex index 4 is out of range (the file has 3)"));
  }
  struct BadLines {
    const char* what;
    const char* lines;  // after the three vertices
    const char* message;
  };
  const BadLines cases[] = {
      {"index 0", "f 0 1 2\n", "m.obj:4:3: vertex index 0 is not allowed"},
      {"relative index before the first vertex", "f -1 -2 -4\n",
       "m.obj:4:9: relative vertex index -4 reaches before the first one"},
      {"normal index past the end", "vn 0 0 1\nf 1//1 2//1 3//2\n",
       "m.obj:5:13: normal index 2 is out of range (the file has 1)"},
      {"texture coordinate index past the end", "vt 0 0\nf 1/1 2/1 3/2\n",
       "m.obj:5:11: texture coordinate index 2 is out of range (the file has 1)"},
      {"relative texture coordinate index before the first one", "vt 0 0\nf 1/-1/1 2/-2/1 3/-1/1\nvn 0 0 1\n",
       "m.obj:5:10: relative texture coordinate index -2 reaches before the first one"},
      {"a corner that is not an index", "f 1 2 x\n", "m.obj:4:7: bad face corner 'x'"},
      {"a face with two corners", "f 1 2\n", "m.obj:4:6: a face needs at least 3 corners, found 2"},
  };
  for (const BadLines& c : cases)
    DYNAMIC_SECTION(c.what) {
      CHECK_THAT(mesh_error(verts + c.lines).message(), Catch::Contains(c.message));
    }
  SECTION("a vertex defined after the face that uses it is fine") {
    const std::string obj = "v 0 0 0\nv 1 0 0\nf 1 2 3\nv 0 1 0\n";
    CHECK(load_with_obj("m.obj", obj, "mesh m.obj\n").meshes.at(0).corners.size() == 3);
  }
}

TEST_CASE("bad OBJ vertex text is an error at the mesh command naming the OBJ line and column",
          "[scene][mesh][errors]") {
  // Every malformed spelling is in obj_reader_test.cpp; here, how the two places combine.
  const clrt::SceneError e = mesh_error("v 0 0 0\nv 1 nan 2\nv 0 1 0\nf 1 2 3\n");
  CHECK(e.where().line == 2);
  CHECK(e.where().column == 3);
  CHECK_THAT(e.what(), Catch::EndsWith("m.obj:2:5: 'nan' is not a finite number") && Catch::Contains(":2:3: error: bad mesh file "));
}

TEST_CASE("a mesh with no triangles is an error", "[scene][mesh][errors]") {
  const clrt::SceneError e = mesh_error("# only points\nv 0 0 0\nv 1 0 0\nv 0 1 0\n");
  CHECK(e.where().line == 2);
  CHECK_THAT(e.message(), Catch::Contains("m.obj: the mesh has no triangles"));
  CHECK_THAT(mesh_error("").message(), Catch::Contains("no triangles"));
}

TEST_CASE("mesh takes one path", "[scene][mesh][errors]") {
  clrt::test::require_error("mesh\n", 1, 5, "wrong number of arguments");
  clrt::test::require_error("mesh my model.obj\n", 1, 9,
                            "wrong number of arguments: mesh takes 1 path");
}

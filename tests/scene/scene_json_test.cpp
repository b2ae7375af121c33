// write_scene_json: every part of a Scene in the document docs/scene-json.md describes.
#include <catch2/catch.hpp>

#include <nlohmann/json.hpp>

#include "scene/scene_json.hpp"
#include "scene_test_support.hpp"

using clrt::Scene;
using clrt::Vec3;
using clrt::test::load_text;
using clrt::test::ScratchDir;
using Json = nlohmann::json;

namespace {

Json dumped(const Scene& scene) {
  std::string text;
  clrt::write_scene_json(scene, [&](const std::string& piece) { text += piece; });
  return Json::parse(text);
}

Json vec(const Vec3& v) { return Json::array({v.x, v.y, v.z}); }

}  // namespace

TEST_CASE("the dump names its format and holds the camera and the scene's settings",
          "[scene][json]") {
  const Scene s = load_text(
      "eye 1 2 3\nlookat 0 1 0\nup 0 0 1\nfov 35\nresolution 40 20\nsamples 6\nmaxdepth 3\n"
      "background 0.1 0.2 0.3\n");
  const Json j = dumped(s);
  CHECK(j["format"] == "clrt-scene");
  CHECK(j["version"] == clrt::kSceneJsonVersion);
  CHECK(j["scene"] == s.path);
  CHECK(j["camera"]["eye"] == vec({1, 2, 3}));
  CHECK(j["camera"]["lookat"] == vec({0, 1, 0}));
  CHECK(j["camera"]["up"] == vec({0, 0, 1}));
  CHECK(j["camera"]["fov_degrees"] == 35.0);
  CHECK(j["camera"]["aspect"] == 2.0);
  CHECK(j["resolution"] == Json::array({40, 20}));
  CHECK(j["samples"] == 6);
  CHECK(j["maxdepth"] == 3);
  CHECK(j["background"] == vec({0.1, 0.2, 0.3}));
}

TEST_CASE("the dump holds every material, the default first", "[scene][json]") {
  const Json j = dumped(load_text("material 0.5 0.25 1 0.1 0.7 0.3 12 0.2 0.4 1.5\nsphere\n"));
  REQUIRE(j["materials"].size() == 2);
  CHECK(j["materials"][0]["kd"] == 0.8);
  const Json& m = j["materials"][1];
  CHECK(m["color"] == vec({0.5, 0.25, 1}));
  CHECK(m["ka"] == 0.1);
  CHECK(m["kd"] == 0.7);
  CHECK(m["ks"] == 0.3);
  CHECK(m["shininess"] == 12.0);
  CHECK(m["kr"] == 0.2);
  CHECK(m["kt"] == 0.4);
  CHECK(m["ior"] == 1.5);
  CHECK(j["objects"][0]["material"] == 1);
}

TEST_CASE("the dump holds every light kind with its own parameters", "[scene][json]") {
  const Json lights = dumped(load_text(
      "light 0.1 0.1 0.1 ambient\nlight 1 2 3 point 4 5 6\nlight 1 1 1 directional 0 -1 -2\n"
      "light 2 2 2 spot 0 4 0 0 -2 0 30 2.5\nlight 3 3 3 area -1 4 -1 2 0 0 0 0 2 9\n"))["lights"];
  REQUIRE(lights.size() == 5);
  CHECK(lights[0] == Json{{"kind", "ambient"}, {"color", vec({0.1, 0.1, 0.1})}});
  CHECK(lights[1] == Json{{"kind", "point"}, {"color", vec({1, 2, 3})}, {"position", vec({4, 5, 6})}});
  CHECK(lights[2] ==
        Json{{"kind", "directional"}, {"color", vec({1, 1, 1})}, {"direction", vec({0, -1, -2})}});
  CHECK(lights[3] == Json{{"kind", "spot"}, {"color", vec({2, 2, 2})}, {"position", vec({0, 4, 0})},
                          {"direction", vec({0, -2, 0})}, {"angle_degrees", 30.0},
                          {"exponent", 2.5}});
  CHECK(lights[4] == Json{{"kind", "area"}, {"color", vec({3, 3, 3})}, {"corner", vec({-1, 4, -1})},
                          {"edge_u", vec({2, 0, 0})}, {"edge_v", vec({0, 0, 2})}, {"samples", 9}});
}

TEST_CASE("the dump holds every shape with its whole transform, object to world",
          "[scene][json]") {
  const Scene s = load_text(
      "rotate 30 1 1 0\nscale 1 2 0.5\ntranslate 1 2 3\n"
      "sphere 1 0 0 2\nplane\ncube\ncylinder\ncone 0.5 0.25\n");
  const Json objects = dumped(s)["objects"];
  REQUIRE(objects.size() == 5);
  const char* shapes[] = {"sphere", "plane", "cube", "cylinder", "cone"};
  for (std::size_t i = 0; i < 5; ++i) {
    INFO(shapes[i]);
    CHECK(objects[i]["shape"] == shapes[i]);
    CHECK(objects[i]["line"] == 4 + i);
    CHECK(objects[i]["column"] == 1);
    for (int row = 0; row < 4; ++row)
      for (int column = 0; column < 4; ++column)
        CHECK(objects[i]["transform"][row][column] == s.instances[i].transform.m[row][column]);
  }
  // A transform command applies after those before it, so the translation is the last column
  // as written: rows of the matrix, not columns.
  CHECK(objects[2]["transform"][0][3] == 1.0);
  CHECK(objects[2]["transform"][2][3] == 3.0);
  CHECK(objects[2]["transform"][3] == Json::array({0.0, 0.0, 0.0, 1.0}));
  CHECK(objects[4]["radii"] == Json::array({0.5, 0.25}));
  CHECK_FALSE(objects[3].contains("radii"));
}

TEST_CASE("the dump holds meshes once, with their normals, and loose triangles in world space",
          "[scene][json]") {
  ScratchDir dir;
  dir.write("quad.obj", "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nvn 0 0 1\nf 1//1 2//1 3//1 4//1\n");
  dir.write("flat.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
  const Scene s = clrt::load_scene(dir.write(
      "scene.ray",
      "mesh quad.obj\ntranslate 0 0 -1\nmaterial 1 0 0 0 1 0 1 0 0\nmesh quad.obj\nmesh flat.obj\n"
      "triangle 0 0 0 1 0 0 0 1 0\n"));
  const Json j = dumped(s);
  REQUIRE(j["meshes"].size() == 2);
  const Json& quad = j["meshes"][0];
  CHECK(quad["path"] == s.meshes[0].path);
  CHECK(quad["positions"] == Json::array({vec({0, 0, 0}), vec({1, 0, 0}), vec({1, 1, 0}), vec({0, 1, 0})}));
  REQUIRE(quad["triangles"].size() == 2);
  for (std::size_t t = 0; t < 2; ++t)
    for (std::size_t k = 0; k < 3; ++k) CHECK(quad["triangles"][t][k] == s.meshes[0].corners[3 * t + k]);
  CHECK(quad["normals"] == Json::array({vec({0, 0, 1})}));
  CHECK(quad["triangle_normals"] == Json::array({Json::array({0, 0, 0}), Json::array({0, 0, 0})}));
  CHECK(j["meshes"][1]["normals"].empty());
  CHECK(j["meshes"][1]["triangle_normals"].empty());

  const Json& objects = j["objects"];
  REQUIRE(objects.size() == 3);
  CHECK(objects[0]["mesh"] == 0);
  CHECK(objects[1]["mesh"] == 0);
  CHECK(objects[2]["mesh"] == 1);
  CHECK(objects[0]["material"] == 0);
  CHECK(objects[1]["material"] == 1);
  CHECK(objects[1]["transform"][2][3] == -1.0);
  REQUIRE(j["triangles"].size() == 1);
  CHECK(j["triangles"][0]["corners"] == Json::array({vec({0, 0, -1}), vec({1, 0, -1}), vec({0, 1, -1})}));
  CHECK(j["triangles"][0]["material"] == 1);
}

TEST_CASE("an NFF scene dumps as clrt reads it", "[scene][json][nff]") {
  const Scene s = load_text(
      "v\nfrom 0 0 5\nat 0 0 0\nup 0 1 0\nangle 45\nhither 0.5\nresolution 8 4\nb 0.1 0.2 0.3\n"
      "l 1 2 3\nf 1 0.5 0.25 0.6 0.3 20 0.2 1.5\ns 1 2 3 0.5\np 3\n0 0 0\n1 0 0\n0 1 0\n",
      "scene.nff");
  const Json j = dumped(s);
  CHECK(j["camera"]["eye"] == vec(s.camera.eye));
  CHECK(j["camera"]["fov_degrees"] == s.camera.fov_degrees);
  CHECK(j["resolution"] == Json::array({8, 4}));
  CHECK(j["background"] == vec({0.1, 0.2, 0.3}));
  REQUIRE(j["lights"].size() == s.lights.size());
  CHECK(j["lights"][0]["position"] == vec({1, 2, 3}));
  REQUIRE(j["objects"].size() == 1);
  CHECK(j["objects"][0]["shape"] == "sphere");
  CHECK(j["objects"][0]["transform"][0] == Json::array({0.5, 0.0, 0.0, 1.0}));
  CHECK(j["materials"].size() == s.materials.size());
  CHECK(j["materials"][1]["ks"] == s.materials[1].ks);
  REQUIRE(j["triangles"].size() == 1);
  CHECK(j["triangles"][0]["material"] == 1);
}

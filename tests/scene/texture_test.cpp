// The texture command, triangles with (u, v), MTL maps, and the checks an image passes before it
// is decoded (docs/scene-format.md#textures).
#include <catch2/catch.hpp>

#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "image/image.hpp"
#include "scene/texture_images.hpp"
#include "png_header.hpp"
#include "scene_test_support.hpp"
#include "shared/texture.h"

using namespace clrt;
using namespace clrt::test;

namespace texture_test {

// A 2x1 PNG: a red texel and a blue one.
void write_png(const ScratchDir& dir, const std::string& name) {
  Rgba8Image image(2, 1, {{255, 0, 0, 255, 0, 0, 255, 255}});
  write_image(dir.write(name, ""), image);  // write() makes the folders
}


TEST_CASE("texture makes a textured copy of the current material", "[scene][texture]") {
  ScratchDir dir;
  write_png(dir, "wood.png");
  const Scene s = load_scene(dir.write("scene.ray",
                                       "material 1 0.5 0.5 0.2 0.8 0 1 0 0\nsphere\n"
                                       "texture color image wood.png scale 2 3 offset 0.5 -1 wrap clamp\nsphere\n"
                                       "texture kr checker 1 1 1 0 0 0\nsphere\n"
                                       "texture color off\nsphere\n"
                                       "texture kt noise 0 0 0 1 1 1 octaves 3\nsphere\n"));
  REQUIRE(s.instances.size() == 5);
  const auto material = [&](std::size_t i) { return s.materials.at(static_cast<std::size_t>(s.instances[i].material)); };
  CHECK(material(0).textures == std::array<int, 4>{-1, -1, -1, -1});
  REQUIRE(material(1).textures[CLRT_TEXTURE_SLOT_COLOR] == 0);
  CHECK(material(1).color.x == 1);  // the copy keeps the rest of the material
  const TextureSpec& image = s.textures.at(0);
  CHECK(image.kind == TextureSpec::Kind::Image);
  CHECK(image.clamp);
  CHECK(image.scale[0] == 2);
  CHECK(image.scale[1] == 3);
  CHECK(image.offset[0] == 0.5);
  CHECK(image.offset[1] == -1);
  REQUIRE(s.texture_images.size() == 1);
  CHECK(s.texture_images[0].width == 2);
  CHECK(s.texture_images[0].srgb == std::vector<std::uint8_t>{255, 0, 0, 0, 0, 255});
  CHECK(material(2).textures == std::array<int, 4>{0, -1, 1, -1});
  CHECK(s.textures.at(1).kind == TextureSpec::Kind::Checker);
  CHECK(material(3).textures == std::array<int, 4>{-1, -1, 1, -1});
  CHECK(material(4).textures == std::array<int, 4>{-1, -1, 1, 2});
  CHECK(s.textures.at(2).octaves == 3);
  CHECK(s.textures.at(2).color1.x == 1);
}

TEST_CASE("an image named by several textures is read once", "[scene][texture]") {
  ScratchDir dir;
  write_png(dir, "a.png");
  const Scene s = load_scene(dir.write("scene.ray", "texture color image a.png\nsphere\ntexture ks image ./a.png scale 4 4\nsphere\n"));
  CHECK(s.textures.size() == 2);
  CHECK(s.texture_images.size() == 1);
}

// The example of docs/scene-format.md#textures, in a scene of scenes/: every file it names is one
// clrt ships.
TEST_CASE("the docs' texture example loads as written beside the shipped scenes", "[scene][texture][docs]") {
  std::ifstream in(std::string(CLRT_SOURCE_DIR) + "/docs/scene-format.md");
  REQUIRE(in);
  std::string example, line;
  bool inside = false;
  while (std::getline(in, line) && example.find("texture color image") == std::string::npos) {
    if (line.rfind("```", 0) == 0) {
      if (!inside) example.clear();
      inside = !inside;
    } else if (inside) {
      example += line + "\n";
    }
  }
  REQUIRE(example.find("texture color image") != std::string::npos);
  ScratchDir dir;
  std::filesystem::create_directory_symlink(std::string(CLRT_SOURCE_DIR) + "/scenes/meshes", dir.file("meshes"));
  const Scene s = load_scene(dir.write("scene.ray", example));
  REQUIRE(s.texture_images.size() == 1);
  CHECK(s.texture_images[0].width > 0);
}

TEST_CASE("a triangle takes (u, v) at its corners", "[scene][texture]") {
  const Scene s = load_text("triangle 0 0 0 0.25 0.5  1 0 0 1 0.5  0 1 0 0.25 1\ntriangle 0 0 0 1 0 0 0 1 0\n");
  REQUIRE(s.triangles.size() == 2);
  CHECK(s.triangles[0].has_uv);
  CHECK(s.triangles[0].uv == std::array<float, 6>{0.25f, 0.5f, 1, 0.5f, 0.25f, 1});
  CHECK(s.triangles[1].v1.x == 1);
  CHECK_FALSE(s.triangles[1].has_uv);
  CHECK(s.triangles[1].uv == std::array<float, 6>{0, 0, 1, 0, 0, 1});
}

TEST_CASE("texture errors point at the word", "[scene][texture][errors]") {
  require_error("texture colour checker 1 1 1 0 0 0\n", 1, 9, "color, ks, kr or kt");
  require_error("texture color stripes\n", 1, 15, "unknown texture");
  require_error("texture color\n", 1, 14, "wrong number of arguments");
  require_error("texture color checker 1 1 1 0 0\n", 1, 32, "two colours");
  require_error("texture color checker 1 1 1 0 0 -1\n", 1, 33, "texture colour");
  require_error("texture color checker 1 1 1 0 0 0 scale 0 1\n", 1, 41, "must not be 0");
  require_error("texture color checker 1 1 1 0 0 0 scale 1\n", 1, 42, "takes 2 numbers");
  require_error("texture color checker 1 1 1 0 0 0 stripes 3\n", 1, 35, "unknown texture option 'stripes'");
  require_error("texture color checker 1 1 1 0 0 0 octaves 17\n", 1, 43, "octaves");  // checked where unused
  require_error("texture color checker 1 1 1 0 0 0 wrap mirror\n", 1, 40, "repeat or clamp");
  require_error("texture color noise 1 1 1 0 0 0 octaves 17\n", 1, 41, "octaves");
  require_error("texture color image a.png wrap mirror\n", 1, 32, "repeat or clamp");
  require_error("texture color image\n", 1, 20, "file name");
  require_error("texture color off now\n", 1, 19, "wrong number of arguments");
  require_error("triangle 0 0 0 0 0 1 0 0 1 0 0 1 0 0\n", 1, 37, "wrong number of arguments");
}

TEST_CASE("a mistyped texture word is offered the nearest one", "[scene][texture][errors]") {
  require_error("texture colour checker 1 1 1 0 0 0\n", 1, 9, "found 'colour' (did you mean 'color'?)");
  require_error("texture KD image a.png\n", 1, 9, "found 'KD' (did you mean 'ks'?)");
  require_error("texture color chekcer 1 1 1 0 0 0\n", 1, 15, "unknown texture 'chekcer' (did you mean 'checker'?");
  require_error("texture color imgae a.png\n", 1, 15, "(did you mean 'image'?");
  require_error("texture color checker 1 1 1 0 0 0 scael 2 2\n", 1, 35,
                "unknown texture option 'scael' (did you mean 'scale'?");
  require_error("texture color noise 1 1 1 0 0 0 Octave 2\n", 1, 33, "(did you mean 'octaves'?");
  require_error("texture color checker 1 1 1 0 0 0 wrap clmap\n", 1, 40,
                "found 'clmap' (did you mean 'clamp'?)");
  // Nothing is offered when nothing is close.
  for (const char* text : {"texture paint checker 1 1 1 0 0 0\n", "texture color stripes\n",
                           "texture color checker 1 1 1 0 0 0 frobnicate 1\n"})
    CHECK(load_error(text).message().find("did you mean") == std::string::npos);
}

TEST_CASE("an option written for another kind of texture is a warning at it, and changes nothing",
          "[scene][texture]") {
  const Scene s = load_text(
      "texture color checker 1 1 1 0 0 0 wrap clamp\nsphere\n"
      "texture color noise 1 1 1 0 0 0 wrap repeat octaves 2\nsphere\n"
      "texture color checker 1 1 1 0 0 0 octaves 3 scale 2 2\nsphere\n");
  REQUIRE(s.textures.size() == 3);
  CHECK_FALSE(s.textures[0].clamp);
  CHECK(s.textures[1].octaves == 2);
  CHECK(s.textures[2].octaves == TextureSpec{}.octaves);
  CHECK(s.textures[2].scale[0] == 2);
  REQUIRE(s.warnings.size() == 3);
  CHECK_THAT(s.warnings[0], Catch::EndsWith(
                                "scene.ray:1:35: warning: wrap applies to image textures only (this is a checker texture); ignored"));
  CHECK_THAT(s.warnings[1], Catch::EndsWith(
                                "scene.ray:3:33: warning: wrap applies to image textures only (this is a noise texture); ignored"));
  CHECK_THAT(s.warnings[2], Catch::EndsWith(
                                "scene.ray:5:35: warning: octaves applies to noise textures only (this is a checker texture); ignored"));
}

TEST_CASE("a missing, malformed or oversized image is an error at the word naming it, before it is decoded",
          "[scene][texture][errors]") {
  ScratchDir dir;
  dir.write("broken.png", "not a png at all");
  dir.write("huge.png", png_header(65536, 65536));
  dir.write("wide.png", png_header(kMaxTextureSide + 1, 1));
  dir.write("photo.png", std::string("\xff\xd8\xff\xe0\x00\x10JFIF", 10));
  const auto error_of = [&](const std::string& line) {
    const SceneError e = load_error_of_file(dir.write("scene.ray", "sphere\n" + line + "\n"));
    INFO(e.what());
    CHECK(e.where().line == 2);
    CHECK(e.where().column == 21);
    return e.message();
  };
  CHECK_THAT(error_of("texture color image missing.png"), Catch::Contains("missing.png"));
  CHECK_THAT(error_of("texture color image broken.png"), Catch::Contains("broken.png"));
  CHECK_THAT(error_of("texture color image huge.png"), Catch::Contains("65536x65536"));
  CHECK_THAT(error_of("texture color image wide.png"), Catch::Contains("at most 16384"));
  // The chunk lengths of a JPEG read as a PNG's made "a chunk declares 1229324289 bytes".
  CHECK_THAT(error_of("texture color image photo.png"),
             Catch::Contains("photo.png: the name says PNG, but the file holds a JPEG image"));
}

TEST_CASE("an MTL map_Kd and map_Ks become textures of their material, and a bump map is a warning",
          "[scene][texture][mtl]") {
  ScratchDir dir;
  write_png(dir, "maps/paint.png");
  dir.write("maps/box.mtl",
            "newmtl painted\nKd 0.5 0.5 0.5\nKs 1 1 1\nmap_Kd -clamp on -s 2 2 -o 0.5 0 paint.png\n"
            "map_Ks paint.png\nbump paint.png\n");
  dir.write("maps/box.obj", "mtllib box.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nvt 1 0\nvt 0 1\nusemtl painted\nf 1/1 2/2 3/3\n");
  const Scene s = load_scene(dir.write("scene.ray", "mesh maps/box.obj\n"));
  REQUIRE(s.meshes.size() == 1);
  const int m = s.meshes[0].name_materials.at(0);
  REQUIRE(m >= 0);
  const MaterialSpec& painted = s.materials.at(static_cast<std::size_t>(m));
  REQUIRE(painted.textures[CLRT_TEXTURE_SLOT_COLOR] >= 0);
  REQUIRE(painted.textures[CLRT_TEXTURE_SLOT_KS] >= 0);
  const TextureSpec& kd = s.textures.at(static_cast<std::size_t>(painted.textures[CLRT_TEXTURE_SLOT_COLOR]));
  CHECK(kd.clamp);
  CHECK(kd.scale[0] == 2);
  CHECK(kd.offset[0] == 0.5);
  CHECK(s.texture_images.size() == 1);  // both maps show one file
  CHECK(s.texture_images.at(0).path.find("maps/paint.png") != std::string::npos);
  REQUIRE(s.warnings.size() == 1);
  CHECK_THAT(s.warnings[0], Catch::Contains("bump map"));
}

TEST_CASE("a .ray texture and an MTL map accept and refuse the same scale and offset", "[scene][texture][mtl]") {
  ScratchDir dir;
  write_png(dir, "a.png");
  dir.write("box.obj", "mtllib box.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nusemtl m\nf 1 2 3\n");
  const auto ray_refuses = [&](const std::string& option, const std::string& values) {
    try {
      load_scene(dir.write("scene.ray", "texture color image a.png " + option + " " + values + "\nsphere\n"));
      return false;
    } catch (const SceneError&) {
      return true;
    }
  };
  const auto mtl_refuses = [&](const std::string& option, const std::string& values) {
    dir.write("box.mtl", "newmtl m\nmap_Kd " + option + " " + values + " a.png\n");
    try {
      load_scene(dir.write("scene.ray", "mesh box.obj\n"));
      return false;
    } catch (const SceneError&) {
      return true;
    }
  };
  for (const char* values : {"0 0", "1 0", "0 1", "-0 2", "-2 0.5", "1e-300 1", "1e12 -1e12", "1e13 1"})
    for (const std::string option : {"scale", "offset"}) {
      INFO(option << " " << values);
      CHECK(ray_refuses(option, values) == mtl_refuses(option == "scale" ? "-s" : "-o", values));
    }
  CHECK(mtl_refuses("-s", "0 0"));
  CHECK_FALSE(mtl_refuses("-s", "2 3 0"));  // w is not used
}

TEST_CASE("a map_Kd that cannot be read is an error at its MTL line", "[scene][texture][mtl][errors]") {
  ScratchDir dir;
  dir.write("box.mtl", "newmtl painted\nKd 1 1 1\nmap_Kd nowhere.png\n");
  dir.write("box.obj", "mtllib box.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nusemtl painted\nf 1 2 3\n");
  const SceneError e = load_error_of_file(dir.write("scene.ray", "mesh box.obj\n"));
  INFO(e.what());
  CHECK(e.where().file.find("box.mtl") != std::string::npos);
  CHECK(e.where().line == 3);
  CHECK(e.where().column == 8);
  CHECK_THAT(e.message(), Catch::Contains("nowhere.png"));
}

}  // namespace texture_test

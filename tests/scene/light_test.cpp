#include <catch2/catch.hpp>

#include <fstream>
#include <map>
#include <sstream>
#include <string>

#include "scene/light_kinds.hpp"
#include "scene_test_support.hpp"

using clrt::Vec3;
using clrt::test::load_text;
using clrt::test::require_error;

TEST_CASE("ambient, point and directional lights", "[scene][lights]") {
  const clrt::Scene s = load_text(
      "light 1 1 1 ambient\nlight 0.6 0.6 0.6 point 3 3 3\nLIGHT 2 0 0 Directional 0 -1 -1\n");
  REQUIRE(s.lights.size() == 3);
  CHECK(s.lights[0].kind == "ambient");
  CHECK(s.lights[0].color == Vec3{1, 1, 1});
  CHECK(s.lights[1].kind == "point");
  CHECK(s.lights[1].color == Vec3{0.6, 0.6, 0.6});
  CHECK(s.lights[1].position == Vec3{3, 3, 3});
  CHECK(s.lights[2].kind == "directional");
  CHECK(s.lights[2].color == Vec3{2, 0, 0});
  CHECK(s.lights[2].direction == Vec3{0, -1, -1});
}

TEST_CASE("spot lights, with and without an exponent", "[scene][lights]") {
  const clrt::Scene s =
      load_text("light 1 1 1 spot 0 4 0 0 -2 0 30\nlight 1 1 1 spot 1 2 3 1 0 0 180 2.5\n");
  REQUIRE(s.lights.size() == 2);
  CHECK(s.lights[0].kind == "spot");
  CHECK(s.lights[0].position == Vec3{0, 4, 0});
  CHECK(s.lights[0].direction == Vec3{0, -2, 0});
  CHECK(s.lights[0].angle_degrees == 30);
  CHECK(s.lights[0].exponent == 0);
  CHECK(s.lights[1].angle_degrees == 180);
  CHECK(s.lights[1].exponent == 2.5);
}

TEST_CASE("area lights, with and without a sample count", "[scene][lights]") {
  const clrt::Scene s =
      load_text("light 3 3 3 area -1 4 -1 2 0 0 0 0 2\nlight 1 1 1 area 0 0 0 1 0 0 0 1 0 9\n");
  REQUIRE(s.lights.size() == 2);
  CHECK(s.lights[0].kind == "area");
  CHECK(s.lights[0].position == Vec3{-1, 4, -1});
  CHECK(s.lights[0].edge_u == Vec3{2, 0, 0});
  CHECK(s.lights[0].edge_v == Vec3{0, 0, 2});
  CHECK(s.lights[0].samples == 16);
  CHECK(s.lights[1].samples == 9);
}

TEST_CASE("lights are not moved by the current transform", "[scene][lights]") {
  const clrt::Scene s = load_text("translate 5 5 5\nscale 2 2 2\nlight 1 1 1 point 1 2 3\n");
  CHECK(s.lights.at(0).position == Vec3{1, 2, 3});
}

TEST_CASE("the lecture's unrepaired light line is a wrong argument count at its 4th number",
          "[scene][lights][errors]") {
  // light 0 6 0 6 0 6 point 3 3 3: six numbers before the kind; the 4th (column 13) is extra.
  require_error(
      "eye 0 0 5\nlight 0 6 0 6 0 6 point 3 3 3\n", 2, 13,
      "wrong number of arguments: light takes 3 numbers (r g b) before its kind, found 6");
}

TEST_CASE("light kind and colour errors", "[scene][lights][errors]") {
  require_error("light 1 1 1 strobe 0 0 0\n", 1, 13, "unknown light kind 'strobe'");
  require_error("light 1 1 1\n", 1, 12, "wrong number of arguments: light needs a kind");
  require_error("light 1 1\n", 1, 10, "wrong number of arguments");
  require_error("light\n", 1, 6, "wrong number of arguments");
  require_error("light 1 1 point 0 0 0\n", 1, 11, "expected a number, found 'point'");
  require_error("light 1 one 1 ambient\n", 1, 9, "expected a number");
  require_error("light 1 1 nan ambient\n", 1, 11, "not a finite number");
}

TEST_CASE("argument counts after the light kind", "[scene][lights][errors]") {
  require_error("light 1 1 1 ambient 0\n", 1, 21, "takes 0 arguments after 'ambient', found 1");
  require_error("light 1 1 1 point 0 0\n", 1, 22, "takes 3 arguments after 'point', found 2");
  require_error("light 1 1 1 directional 0 -1 0 1\n", 1, 32, "found 4");
  require_error("light 1 1 1 spot 0 0 0 0 -1 0\n", 1, 30,
                "takes 7 or 8 arguments after 'spot', found 6");
  require_error("light 1 1 1 spot 0 0 0 0 -1 0 30 1 1\n", 1, 36, "found 9");
  require_error("light 1 1 1 area 0 0 0 1 0 0 0 1\n", 1, 33,
                "takes 9 or 10 arguments after 'area'");
  require_error("light 1 1 1 area 0 0 0 1 0 0 0 1 0 4 4\n", 1, 38, "found 11");
}

TEST_CASE("light range rules", "[scene][lights][errors]") {
  require_error("light 1 1 1 directional 0 0 0\n", 1, 25,
                "light direction must not be a zero-length vector");
  require_error("light 1 1 1 directional 1e200 0 0\n", 1, 25, "'1e200' is too large");
  require_error("light 1 1 1 spot 0 4 0 0 0 0 30\n", 1, 24,
                "spot axis must not be a zero-length vector");
  require_error("light 1 1 1 spot 0 4 0 0 -1 0 0\n", 1, 31, "spot angle must be > 0 and <= 180");
  require_error("light 1 1 1 spot 0 4 0 0 -1 0 180.5\n", 1, 31, "spot angle");
  require_error("light 1 1 1 spot 0 4 0 0 -1 0 45 -1\n", 1, 34, "spot exponent must be >= 0");
  require_error("light 1 1 1 area 0 4 0 0 0 0 0 0 1\n", 1, 24,
                "edge u must not be a zero-length vector");
  require_error("light 1 1 1 area 0 4 0 1 0 0 0 0 0\n", 1, 30,
                "edge v must not be a zero-length vector");
  require_error("light 1 1 1 area 0 4 0 1 0 0 0 0 1 0\n", 1, 36, "whole number from 1 to 65536");
  // Edges the device cannot make an area of in single precision: every path-mode sample of
  // such a light was NaN.
  require_error("light 1 1 1 area 0 4 0 1 0 0 2 0 0\n", 1, 24, "edges u and v are parallel");
  require_error("light 1 1 1 area 0 4 0 1 0 0 1 1e-5 0\n", 1, 24, "edges u and v are parallel");
  require_error("light 1 1 1 area 0 4 0 1e-12 0 0 0 0 1e-12\n", 1, 24, "too small or too large");
  require_error("light 1 1 1 area 0 4 0 1e11 0 0 0 0 1e11\n", 1, 24, "too small or too large");
  CHECK(load_text("light 1 1 1 area 0 4 0 1e-9 0 0 0 0 1e-9\nlight 1 1 1 area 0 4 0 1 0 0 1 1e-3 0\n")
            .lights.size() == 2);
  require_error("light 1 1 1 area 0 4 0 1 0 0 0 0 1 2.5\n", 1, 36, "whole number from 1 to 65536");
}

// The kind table is the one list of kinds: the reader, the device's light table and the docs all
// follow its rows.
TEST_CASE("every light kind's row: the device kind of its file and its syntax in the docs",
          "[scene][lights]") {
  std::ifstream in("docs/scene-format.md");
  REQUIRE(in);
  std::stringstream text;
  text << in.rdbuf();
  const std::string docs = text.str();
  std::size_t documented = 0;
  for (std::size_t at = docs.find("| `light r g b "); at != std::string::npos;
       at = docs.find("| `light r g b ", at + 1))
    ++documented;
  const auto& table = clrt::light_kind_table();
  CHECK(documented == table.size());
  // The device's kinds, one per file of kernels/render/lights/, by the name of the file.
  std::map<std::string, clrt::dev::u32> device_kinds = {
#define CLRT_DEVICE_KIND(KIND, name) {#name, clrt::dev::CLRT_LIGHT_##KIND},
      CLRT_LIGHT_KINDS(CLRT_DEVICE_KIND)
#undef CLRT_DEVICE_KIND
  };
  CHECK(device_kinds.size() == clrt::dev::CLRT_LIGHT_KIND_COUNT);
  for (const clrt::LightKindEntry& entry : table) {
    INFO(entry.name);
    const std::string syntax = std::string(entry.name) + (*entry.syntax ? " " : "") + entry.syntax;
    CHECK(docs.find("| `light r g b " + syntax + "` |") != std::string::npos);
    CHECK(clrt::find_light_kind(entry.name) == &entry);
    if (!entry.to_device) continue;
    clrt::LightSpec spec;
    spec.kind = entry.name;
    spec.direction = spec.edge_u = Vec3{1, 0, 0};
    spec.edge_v = Vec3{0, 1, 0};
    clrt::dev::Light record{};
    record.kind = ~0u;
    record.samples = 1;
    entry.to_device(spec, record);
    // The record is the kind whose device file has the row's name.
    const auto device = device_kinds.find(entry.name);
    REQUIRE(device != device_kinds.end());
    CHECK(record.kind == device->second);
    device_kinds.erase(device);
  }
  // Every kind the device knows is some row's, but the two that no `light` command makes
  // (src/render/frame_setup.cpp): path mode's glow light, made of the scene's glowing geometry,
  // and the environment, made by `environment`.
  CHECK(device_kinds.erase("glow") == 1);
  CHECK(device_kinds.erase("environment") == 1);
  CHECK(device_kinds.empty());
}

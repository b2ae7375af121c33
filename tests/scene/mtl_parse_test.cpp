// The MTL reader (scene/mtl_reader.hpp): what each statement gives, where each error points, and
// one warning per thing clrt does not render.
#include <catch2/catch.hpp>

#include <string>

#include "scene/mtl_reader.hpp"

using clrt::MtlLibrary;
using clrt::parse_mtl;
using clrt::SceneError;

namespace mtl_parse_test {

// Parses `text` expecting an error; returns it.
SceneError mtl_error(const std::string& text) {
  try {
    parse_mtl(text, "lib.mtl");
  } catch (const SceneError& e) {
    return e;
  }
  FAIL("no error for: " << text);
  throw std::logic_error("unreachable");
}

void check_error(const std::string& text, int line, int column, const std::string& part) {
  INFO(text);
  const SceneError e = mtl_error(text);
  CHECK(e.where().file == "lib.mtl");
  CHECK(e.where().line == line);
  CHECK(e.where().column == column);
  CHECK_THAT(e.message(), Catch::Contains(part));
}

TEST_CASE("an exported MTL library gives each material what it says", "[scene][mtl]") {
  const MtlLibrary lib = parse_mtl(
      "# Blender MTL File\r\n"
      "newmtl Body Paint\r\n"
      "Ns 225.000000\r\nKa 1.000000 1.000000 1.000000\r\nKd 0.800000 0.100000 0.050000\r\n"
      "Ks 0.5 0.5 0.5\r\nKe 0 0 0\r\nNi 1.450000\r\nd 1.000000\r\nillum 2\r\n"
      "map_Kd -clamp on -s 2 3 -o 0.5 textures/car paint.png\r\n"
      "\r\n"
      "newmtl glass\nKd 0.2\nTr 0.75\nillum 7\nbump -bm 0.4 bumps.png   \nmap_Ks spec.png # shine\n",
      "lib.mtl");
  REQUIRE(lib.materials.size() == 2);
  const clrt::MtlMaterial& paint = lib.materials[0];
  CHECK(paint.name == "Body Paint");
  CHECK(paint.where.line == 2);
  CHECK(paint.where.column == 8);
  CHECK(*paint.ns == 225);
  CHECK(paint.kd->x == Approx(0.8));
  CHECK(paint.kd->z == Approx(0.05));
  CHECK(paint.ks->y == Approx(0.5));
  CHECK(paint.ke->x == 0);
  CHECK(*paint.ni == Approx(1.45));
  CHECK(*paint.dissolve == 1);
  CHECK(*paint.illum == 2);
  REQUIRE(paint.map_kd);
  CHECK(paint.map_kd->path == "textures/car paint.png");
  CHECK(paint.map_kd->where.line == 11);
  CHECK(paint.map_kd->where.column == 32);
  CHECK(paint.map_kd->clamp);
  CHECK(paint.map_kd->scale.x == 2);
  CHECK(paint.map_kd->scale.y == 3);
  CHECK(paint.map_kd->scale.z == 1);
  CHECK(paint.map_kd->offset.x == 0.5);
  const clrt::MtlMaterial& glass = lib.materials[1];
  CHECK(glass.kd->y == Approx(0.2));  // one number: grey
  CHECK(*glass.dissolve == Approx(0.25));
  REQUIRE(glass.map_bump);
  CHECK(glass.map_bump->path == "bumps.png");
  CHECK(glass.map_bump->bump_multiplier == Approx(0.4));
  REQUIRE(glass.map_ks);
  CHECK(glass.map_ks->path == "spec.png");
  REQUIRE(lib.warnings.size() == 1);
  CHECK(lib.warnings[0] == "lib.mtl:4:1: warning: 'Ka' is not rendered by clrt; ignored");
}

TEST_CASE("each thing clrt does not render is one warning at its first place", "[scene][mtl]") {
  const MtlLibrary lib = parse_mtl(
      "newmtl a\nKa 1 1 1\nTf 1 1 1\nmap_Kd -blendu off a.png\n"
      "newmtl b\nKa 0 0 0\nmap_Kd -blendu on b.png\nKd spectral ident.rfl\nPr 0.5\nd -halo 0.5\n",
      "lib.mtl");
  CHECK(lib.warnings == std::vector<std::string>{
                            "lib.mtl:2:1: warning: 'Ka' is not rendered by clrt; ignored",
                            "lib.mtl:3:1: warning: 'Tf' is not rendered by clrt; ignored",
                            "lib.mtl:4:8: warning: 'map_Kd -blendu' is not rendered by clrt; ignored",
                            "lib.mtl:8:4: warning: 'Kd spectral' is not rendered by clrt; ignored",
                            "lib.mtl:9:1: warning: 'Pr' is not rendered by clrt; ignored",
                            "lib.mtl:10:3: warning: 'd -halo' is not rendered by clrt; ignored"});
  CHECK_FALSE(lib.materials[1].kd);
}

TEST_CASE("a repeated material name: the later definition is the one found", "[scene][mtl]") {
  const MtlLibrary lib = parse_mtl("newmtl x\nKd 1 0 0\nnewmtl x\nKd 0 1 0\nKd 0 0 1\n", "lib.mtl");
  REQUIRE(lib.materials.size() == 2);
  CHECK(lib.materials[1].kd->z == 1);  // within a block, the last statement counts
}

TEST_CASE("malformed MTL statements are errors at their word", "[scene][mtl][errors]") {
  check_error("Kd 1 1 1\n", 1, 1, "before the first newmtl");
  check_error("newmtl\n", 1, 7, "needs a material name");
  check_error("newmtl a\nKd 1 1\n", 2, 7, "missing");
  check_error("newmtl a\nKd 1 1 1 1\n", 2, 10, "unexpected");
  check_error("newmtl a\nKd 1 x 1\n", 2, 6, "'x'");
  check_error("newmtl a\nKd -1 0 0\n", 2, 4, "must be in");
  check_error("newmtl a\nNs -2\n", 2, 4, "Ns");
  check_error("newmtl a\nNi 0\n", 2, 4, "Ni");
  check_error("newmtl a\nd 1.5\n", 2, 3, "d must be in");
  check_error("newmtl a\nTr 2\n", 2, 4, "Tr");
  check_error("newmtl a\nillum 11\n", 2, 7, "illum");
  check_error("newmtl a\nillum 2.5\n", 2, 7, "whole number");
  check_error("newmtl a\nKd nan 0 0\n", 2, 4, "'nan'");
  check_error("newmtl a\nmap_Kd\n", 2, 7, "needs a file name");
  check_error("newmtl a\nmap_Kd -clamp on\n", 2, 17, "needs a file name");
  check_error("newmtl a\nmap_Kd -clamp maybe a.png\n", 2, 15, "on or off");
  check_error("newmtl a\nmap_Kd -s a.png\n", 2, 16, "needs a file name after its options");
  check_error("newmtl a\nmap_Kd -s x a.png\n", 2, 11, "-s needs 1 value");
  check_error("newmtl a\nmap_Kd -zoom 2 a.png\n", 2, 8, "unknown option");
  check_error("newmtl a\nmap_Kd -bm 2 a.png\n", 2, 8, "bump maps");
}

TEST_CASE("hostile MTL text is read or refused, never a crash", "[scene][mtl][errors]") {
  const std::string nul("newmtl a\0b\nKd 1 1 1\n", 20);
  CHECK(parse_mtl(nul, "lib.mtl").materials.size() == 1);
  const std::string long_name = "newmtl " + std::string(1 << 20, 'n') + "\n";
  CHECK(parse_mtl(long_name, "lib.mtl").materials[0].name.size() == (1u << 20));
  check_error("newmtl a\nNs 1e999\n", 2, 4, "Ns");
  CHECK(parse_mtl("", "lib.mtl").materials.empty());
  CHECK(parse_mtl("\n\n# only comments\n   \t\n", "lib.mtl").materials.empty());
  CHECK(parse_mtl("newmtl a", "lib.mtl").materials.size() == 1);  // no final line end
}

}  // namespace mtl_parse_test

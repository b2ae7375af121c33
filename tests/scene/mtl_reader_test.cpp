// The MTL reader (scene/mtl_reader.hpp) statement by statement: every value and map option it
// keeps, the place of every error and warning, and hostile text.
#include <catch2/catch.hpp>

#include <cstdint>
#include <string>
#include <vector>

#include "scene/mtl_reader.hpp"

namespace mtl_reader_test {

using clrt::MtlLibrary;
using clrt::MtlMaterial;
using clrt::MtlTextureRef;
using clrt::parse_mtl;
using clrt::SceneError;
using clrt::Vec3;

MtlLibrary read(const std::string& text) { return parse_mtl(text, "lib.mtl"); }

// The one material of `text`, after "newmtl m\n".
MtlMaterial only_material(const std::string& statements) {
  const MtlLibrary lib = read("newmtl m\n" + statements);
  REQUIRE(lib.materials.size() == 1);
  return lib.materials[0];
}

// The map_Kd (or map_bump, for bump statements) of one material.
MtlTextureRef only_map(const std::string& statement) {
  const MtlMaterial m = only_material(statement + "\n");
  const std::optional<MtlTextureRef>& map = m.map_kd ? m.map_kd : m.map_bump;
  REQUIRE(map);
  return *map;
}

// The error that `text` gives, which must start with `place` ("lib.mtl:LINE:COLUMN: error: ")
// and mention `part`.
void check_refused(const std::string& text, const std::string& place, const std::string& part) {
  INFO("text: " << text);
  try {
    read(text);
    FAIL("no error");
  } catch (const SceneError& e) {
    CHECK_THAT(e.what(), Catch::StartsWith(place + ": error: "));
    CHECK_THAT(e.message(), Catch::Contains(part));
  }
}

std::vector<std::string> warnings_of(const std::string& text) { return read(text).warnings; }

std::string ignored(const std::string& place, const std::string& what) {
  return "lib.mtl:" + place + ": warning: '" + what + "' is not rendered by clrt; ignored";
}

TEST_CASE("a Blender MTL export gives both materials every value it writes", "[scene][mtl]") {
  const MtlLibrary lib = read(
      "# Blender 3.6.0 MTL File: 'scene.blend'\n"
      "# www.blender.org\n"
      "\n"
      "newmtl Material.001\n"
      "Ns 250.000000\n"
      "Ka 1.000000 1.000000 1.000000\n"
      "Kd 0.800000 0.050000 0.020000\n"
      "Ks 0.500000 0.500000 0.500000\n"
      "Ke 0.000000 0.000000 0.000000\n"
      "Ni 1.450000\n"
      "d 1.000000\n"
      "illum 2\n"
      "map_Kd textures/wood.png\n"
      "\n"
      "newmtl Lamp\n"
      "Ns 0.000000\n"
      "Ka 1.000000 1.000000 1.000000\n"
      "Kd 0.000000 0.000000 0.000000\n"
      "Ks 0.000000 0.000000 0.000000\n"
      "Ke 4.000000 3.500000 3.000000\n"
      "Ni 1.000000\n"
      "d 0.250000\n"
      "illum 1\n");
  REQUIRE(lib.materials.size() == 2);
  const MtlMaterial& wood = lib.materials[0];
  CHECK(wood.name == "Material.001");
  CHECK(wood.where.file == "lib.mtl");
  CHECK(wood.where.line == 4);
  CHECK(wood.where.column == 8);
  CHECK(*wood.ns == 250);
  CHECK(*wood.kd == Vec3{0.8, 0.05, 0.02});
  CHECK(*wood.ks == Vec3{0.5, 0.5, 0.5});
  CHECK(*wood.ke == Vec3{0, 0, 0});
  CHECK(*wood.ni == 1.45);
  CHECK(*wood.dissolve == 1);
  CHECK(*wood.illum == 2);
  REQUIRE(wood.map_kd);
  CHECK(wood.map_kd->path == "textures/wood.png");
  CHECK(wood.map_kd->where.line == 13);
  CHECK(wood.map_kd->where.column == 8);
  CHECK_FALSE(wood.map_kd->clamp);
  CHECK(wood.map_kd->scale == Vec3{1, 1, 1});
  CHECK(wood.map_kd->offset == Vec3{0, 0, 0});
  CHECK_FALSE(wood.map_ks);
  CHECK_FALSE(wood.map_bump);
  const MtlMaterial& lamp = lib.materials[1];
  CHECK(lamp.name == "Lamp");
  CHECK(lamp.where.line == 15);
  CHECK(*lamp.ke == Vec3{4, 3.5, 3});
  CHECK(*lamp.dissolve == 0.25);
  CHECK(*lamp.illum == 1);
  CHECK_FALSE(lamp.map_kd);
  CHECK(lib.warnings == std::vector<std::string>{ignored("6:1", "Ka")});
  CHECK(lib.find("Lamp") == &lib.materials[1]);
  CHECK(lib.find("Material.001") == &lib.materials[0]);
  CHECK(lib.find("lamp") == nullptr);  // names are case-sensitive
}

TEST_CASE("a material without statements has every value absent", "[scene][mtl]") {
  const MtlMaterial m = only_material("");
  CHECK_FALSE(m.kd);
  CHECK_FALSE(m.ks);
  CHECK_FALSE(m.ke);
  CHECK_FALSE(m.ns);
  CHECK_FALSE(m.ni);
  CHECK_FALSE(m.dissolve);
  CHECK_FALSE(m.illum);
  CHECK_FALSE(m.map_kd);
  CHECK_FALSE(m.map_ks);
  CHECK_FALSE(m.map_bump);
}

TEST_CASE("one number makes a grey colour", "[scene][mtl]") {
  const MtlMaterial m = only_material("Kd 0.25\nKs 2\nKe 7.5   # a bright grey\n");
  CHECK(*m.kd == Vec3{0.25, 0.25, 0.25});
  CHECK(*m.ks == Vec3{2, 2, 2});  // above 1 is allowed
  CHECK(*m.ke == Vec3{7.5, 7.5, 7.5});
}

TEST_CASE("Tr is the transparency, stored as the dissolve 1 - t", "[scene][mtl]") {
  CHECK(*only_material("Tr 0.25\n").dissolve == 0.75);
  CHECK(*only_material("Tr 0\n").dissolve == 1);
  CHECK(*only_material("Tr 1\n").dissolve == 0);
  CHECK(*only_material("d 0.5\nTr 0.1\n").dissolve == Approx(0.9));  // the last one counts
  CHECK(*only_material("Tr 0.1\nd 0.5\n").dissolve == 0.5);
}

TEST_CASE("the edges of every range are accepted", "[scene][mtl]") {
  const MtlMaterial m = only_material("Kd 0 0 0\nKs 1e12 0 0\nNs 0\nNi 1e-9\nd 0\nillum 0\n");
  CHECK(*m.kd == Vec3{0, 0, 0});
  CHECK(m.ks->x == 1e12);
  CHECK(*m.ns == 0);
  CHECK(*m.ni == 1e-9);
  CHECK(*m.dissolve == 0);
  CHECK(*m.illum == 0);
  CHECK(*only_material("illum 10\n").illum == 10);
  CHECK(*only_material("illum 4.0\n").illum == 4);  // a whole number, however written
  CHECK(*only_material("d 1\n").dissolve == 1);
  CHECK(*only_material("Kd +.5 1e-1 -0\n").kd == Vec3{0.5, 0.1, 0});
}

TEST_CASE("a repeated statement within a material: the last one counts, silently", "[scene][mtl]") {
  const MtlLibrary lib = read("newmtl m\nKd 1 0 0\nNs 10\nmap_Kd a.png\nKd 0 0 1\nNs 20\nmap_Kd b.png\n");
  CHECK(*lib.materials[0].kd == Vec3{0, 0, 1});
  CHECK(*lib.materials[0].ns == 20);
  CHECK(lib.materials[0].map_kd->path == "b.png");
  CHECK(lib.warnings.empty());
}

TEST_CASE("map options -clamp -s -o and -bm are kept", "[scene][mtl]") {
  CHECK(only_map("map_Kd -clamp on a.png").clamp);
  CHECK_FALSE(only_map("map_Kd -clamp off a.png").clamp);
  CHECK_FALSE(only_map("map_Kd -clamp on -clamp off a.png").clamp);
  CHECK(only_map("map_Kd -s 2 a.png").scale == Vec3{2, 1, 1});
  CHECK(only_map("map_Kd -s 2 3 a.png").scale == Vec3{2, 3, 1});
  CHECK(only_map("map_Kd -s 2 3 4 a.png").scale == Vec3{2, 3, 4});
  CHECK(only_map("map_Kd -o 0.5 a.png").offset == Vec3{0.5, 0, 0});
  CHECK(only_map("map_Kd -o -0.5 -1 a.png").offset == Vec3{-0.5, -1, 0});
  CHECK(only_map("map_Kd -o 1 2 -3 a.png").offset == Vec3{1, 2, -3});
  // A later option starts anew from its defaults.
  CHECK(only_map("map_Kd -s 2 3 4 -s 5 a.png").scale == Vec3{5, 1, 1});
  CHECK(only_map("map_bump -bm 0.5 bumps.png").bump_multiplier == 0.5);
  CHECK(only_map("bump -bm -2 bumps.png").bump_multiplier == -2);
  CHECK(only_map("bump bumps.png").bump_multiplier == 1);
  const MtlTextureRef all = only_map("map_Kd -o 0.1 0.2 -clamp on -s 4 4 a.png");
  CHECK(all.clamp);
  CHECK(all.scale == Vec3{4, 4, 1});
  CHECK(all.offset == Vec3{0.1, 0.2, 0});
  CHECK(all.path == "a.png");
  CHECK(all.where.column == 36);
  // A fourth number is no value of -s: it starts the file name.
  CHECK(only_map("map_Kd -s 1 2 3 4.png").path == "4.png");
  CHECK(only_map("map_Kd -s 1 2 3 4 x.png").path == "4 x.png");
  // The last word is the file name even when it reads as a number.
  CHECK(only_map("map_Kd -s 2 3").path == "3");
  CHECK(only_map("map_Kd -clamp on on").path == "on");
}

TEST_CASE("a map's w, which clrt does not use, is a warning unless it is the default", "[scene][mtl]") {
  CHECK(warnings_of("newmtl a\nmap_Kd -s 2 2 1 -o 0.5 0.5 0 a.png\n").empty());
  const std::string unused = ": clrt's textures have two coordinates, so its third value (w) is not used; ignored";
  CHECK(warnings_of("newmtl a\nmap_Kd -s 2 2 3 a.png\nmap_Ks -o 0 0 0.5 -o 1 1 2 b.png\nmap_Kd -s 1 1 2 a.png\n") ==
        std::vector<std::string>{"lib.mtl:2:15: warning: map_Kd -s" + unused, "lib.mtl:3:15: warning: map_Ks -o" + unused});
}

TEST_CASE("map_Kd map_Ks map_bump and bump fill their own slots", "[scene][mtl]") {
  const MtlMaterial m = only_material("map_Kd d.png\nmap_Ks s.png\nbump b.png\n");
  CHECK(m.map_kd->path == "d.png");
  CHECK(m.map_ks->path == "s.png");
  CHECK(m.map_bump->path == "b.png");
  CHECK(only_material("map_bump first.png\nbump second.png\n").map_bump->path == "second.png");
}

TEST_CASE("map options clrt does not render are read past, one warning each", "[scene][mtl]") {
  const MtlLibrary lib = read(
      "newmtl m\n"
      "map_Kd -blendu on -blendv off -cc on -mm 0 1 -t 0.1 -texres 512 -imfchan l -boost 2 a b.png\n"
      "map_Kd -blendu off -t 1 2 3 -mm -0.5 2 c.png\n"
      "map_Ks -blendu on s.png\n"
      "bump -imfchan z -bm 3 -t 1 2 n.png\n");
  const MtlMaterial& m = lib.materials[0];
  CHECK(m.map_kd->path == "c.png");
  CHECK(m.map_ks->path == "s.png");
  CHECK(m.map_bump->path == "n.png");
  CHECK(m.map_bump->bump_multiplier == 3);
  CHECK(lib.warnings == std::vector<std::string>{
                            ignored("2:8", "map_Kd -blendu"), ignored("2:19", "map_Kd -blendv"),
                            ignored("2:31", "map_Kd -cc"), ignored("2:38", "map_Kd -mm"),
                            ignored("2:46", "map_Kd -t"), ignored("2:53", "map_Kd -texres"),
                            ignored("2:65", "map_Kd -imfchan"), ignored("2:76", "map_Kd -boost"),
                            ignored("4:8", "map_Ks -blendu"), ignored("5:6", "bump -imfchan"),
                            ignored("5:23", "bump -t")});
  CHECK(only_map("map_Kd -blendu on a.png").path == "a.png");
  for (const char* channel : {"r", "g", "b", "m", "l", "z"})
    CHECK(only_map(std::string("map_Kd -imfchan ") + channel + " a.png").path == "a.png");
}

TEST_CASE("file names and material names keep their spaces, and lose trailing blanks", "[scene][mtl]") {
  const MtlLibrary lib = read("newmtl  my  red paint \t \nmap_Kd -s 2 textures/old wood  grain.png \t  # oak\n");
  const MtlMaterial& m = lib.materials[0];
  CHECK(m.name == "my  red paint");
  CHECK(m.where.column == 9);
  CHECK(m.map_kd->path == "textures/old wood  grain.png");
  CHECK(m.map_kd->where.line == 2);
  CHECK(m.map_kd->where.column == 13);
  CHECK(only_map("map_Kd C:\\textures\\wood.png").path == "C:\\textures\\wood.png");
  CHECK(only_map("map_Kd -").path == "-");  // a lone dash is no option
  CHECK(lib.find("my  red paint") == &lib.materials[0]);
}

TEST_CASE("CRLF line ends read as LF ones", "[scene][mtl]") {
  const std::string lf =
      "# exported on Windows\nnewmtl a b\nKd 0.5 0.25 1\nNs 10\nd 0.5\nillum 2\nmap_Kd -clamp on my tex.png\n"
      "Ka 1 1 1\n\nnewmtl c\nKd 1\n";
  std::string crlf;
  for (const char c : lf) crlf += c == '\n' ? std::string("\r\n") : std::string(1, c);
  const MtlLibrary unix_lib = read(lf);
  const MtlLibrary windows_lib = read(crlf);
  REQUIRE(windows_lib.materials.size() == 2);
  const MtlMaterial& a = windows_lib.materials[0];
  CHECK(a.name == "a b");
  CHECK(*a.kd == Vec3{0.5, 0.25, 1});
  CHECK(*a.illum == 2);
  CHECK(a.map_kd->path == "my tex.png");
  CHECK(a.map_kd->clamp);
  CHECK(windows_lib.materials[1].name == "c");
  CHECK(*windows_lib.materials[1].kd == Vec3{1, 1, 1});
  CHECK(windows_lib.warnings == unix_lib.warnings);
  CHECK(windows_lib.warnings == std::vector<std::string>{ignored("8:1", "Ka")});
}

TEST_CASE("comments and blank lines are skipped wherever they are", "[scene][mtl]") {
  const MtlLibrary lib = read(
      "#newmtl not a material\n"
      "   # indented comment\n"
      "\t\n"
      "\n"
      "newmtl a#1 # the name keeps a '#' inside a word\n");
  REQUIRE(lib.materials.size() == 1);
  CHECK(lib.materials[0].name == "a#1");
  CHECK(lib.materials[0].where.line == 5);
  CHECK(lib.warnings.empty());
  // A '#' glued to a number is part of the word, so the number is malformed.
  check_refused("newmtl a\nKd 1 0 0#x\n", "lib.mtl:2:8", "'0#x'");
  CHECK(*only_material("Kd 1 0 0 #x\n").kd == Vec3{1, 0, 0});
  CHECK(only_material("map_Kd a.png#1 #2\n").map_kd->path == "a.png#1");
  CHECK(read("").materials.empty());
  CHECK(read("# nothing\n\n").materials.empty());
  CHECK(read("newmtl last").materials[0].name == "last");  // no final line end
}

TEST_CASE("a line ending in a backslash is refused at the backslash", "[scene][mtl][errors]") {
  check_refused("newmtl a\nKd 1 1 \\\n 1\n", "lib.mtl:2:8", "continues on the next line");
  check_refused("newmtl a\nmap_Kd tex\\\n", "lib.mtl:2:11", "continues on the next line");
  check_refused("newmtl a\nmap_Kd tex\\  \r\n", "lib.mtl:2:11", "continues on the next line");
  check_refused("newmtl a \\\n", "lib.mtl:1:10", "continues on the next line");
  check_refused("Ka 1 \\\n", "lib.mtl:1:6", "continues on the next line");
  // Within a comment it is just a character.
  CHECK(*only_material("Kd 1 1 1 # see \\\n").kd == Vec3{1, 1, 1});
  CHECK(read("# \\\nnewmtl a\n").materials.size() == 1);
}

std::string read_as(const std::string& place, const std::string& written, const std::string& keyword) {
  return "lib.mtl:" + place + ": warning: '" + written + "' is read as '" + keyword +
         "' (MTL keywords are case-sensitive)";
}

TEST_CASE("a keyword in another case is read as the keyword, with a note once per spelling", "[scene][mtl]") {
  const MtlLibrary lib = read("NEWMTL a\nkd 1 0 0\nKD 0 1 0\nMap_Kd a.png\nmap_kd b.png\nkd 0 0 1\nD 0.5\n");
  REQUIRE(lib.materials.size() == 1);
  CHECK(*lib.materials[0].kd == Vec3{0, 0, 1});
  CHECK(lib.materials[0].map_kd->path == "b.png");
  CHECK(*lib.materials[0].dissolve == 0.5);
  CHECK(lib.warnings == std::vector<std::string>{read_as("1:1", "NEWMTL", "newmtl"), read_as("2:1", "kd", "Kd"),
                                                 read_as("3:1", "KD", "Kd"), read_as("4:1", "Map_Kd", "map_Kd"),
                                                 read_as("5:1", "map_kd", "map_Kd"), read_as("7:1", "D", "d")});
  // A keyword clrt does not render stays a note in any case, not a misspelt Kd.
  CHECK(warnings_of("newmtl a\nka 1 1 1\n") == std::vector<std::string>{ignored("2:1", "ka")});
}

TEST_CASE("a misspelt keyword is a warning naming the nearest keyword", "[scene][mtl]") {
  const MtlLibrary lib = read("newmtl a\nKdd 1 0 0\nmap_Kdd a.png\nnewmlt b\nillumm 2\nKdd 1\n");
  REQUIRE(lib.materials.size() == 1);
  CHECK_FALSE(lib.materials[0].kd);
  CHECK_FALSE(lib.materials[0].map_kd);
  CHECK(lib.warnings ==
        std::vector<std::string>{"lib.mtl:2:1: warning: unknown statement 'Kdd' (did you mean 'Kd'?); ignored",
                                 "lib.mtl:3:1: warning: unknown statement 'map_Kdd' (did you mean 'map_Kd'?); ignored",
                                 "lib.mtl:4:1: warning: unknown statement 'newmlt' (did you mean 'newmtl'?); ignored",
                                 "lib.mtl:5:1: warning: unknown statement 'illumm' (did you mean 'illum'?); ignored"});
  check_refused("newmlt a\n", "lib.mtl:1:1", "'newmlt' before the first newmtl (did you mean 'newmtl'?)");
  check_refused("Ka 1 1 1\n", "lib.mtl:1:1", "'Ka' before the first newmtl");
  CHECK_THAT(warnings_of("newmtl a\nframbozzle 1\n")[0], !Catch::Contains("did you mean"));
}

TEST_CASE("a misspelt map option or value names the nearest one", "[scene][mtl][errors]") {
  check_refused("newmtl a\nmap_Kd -clmap on a.png\n", "lib.mtl:2:8",
                "unknown option '-clmap' of map_Kd (did you mean '-clamp'?)");
  check_refused("newmtl a\nmap_Kd -S 2 a.png\n", "lib.mtl:2:8", "(did you mean '-s'?)");
  check_refused("newmtl a\nmap_Kd -clamp ON a.png\n", "lib.mtl:2:15", "found 'ON' (did you mean 'on'?)");
}

TEST_CASE("every statement clrt does not render is one warning, at its first place", "[scene][mtl]") {
  const std::vector<std::string> keywords = {
      "Ka", "Tf", "sharpness", "map_Ka", "map_d", "map_Ns", "disp", "decal", "refl", "Pr", "Pm",
      "Ps", "Pc", "Pcr", "aniso", "anisor", "norm", "map_Pr", "map_Pm", "map_Ke", "frobnicate"};
  std::string text = "newmtl a\n";
  for (const std::string& k : keywords) text += "  " + k + " 1 2 -3 x.png\n";
  text += "newmtl b\n";
  for (const std::string& k : keywords) text += k + " 0\n";
  std::vector<std::string> expected;
  for (std::size_t i = 0; i < keywords.size(); ++i)
    expected.push_back(ignored(std::to_string(i + 2) + ":3", keywords[i]));
  const MtlLibrary lib = read(text);
  CHECK(lib.warnings == expected);
  CHECK(lib.materials.size() == 2);
}

TEST_CASE("spectral and XYZ colours and d -halo are one warning each and change nothing",
          "[scene][mtl]") {
  const MtlLibrary lib = read(
      "newmtl a\nKd 0.5 0.5 0.5\nKd spectral ident.rfl 1\nKs xyz 1 1 1\nKe spectral glow.rfl\n"
      "Kd xyz 0.1\nd 0.5\nd -halo 0.25\nTr -halo 0.1\nKs spectral x.rfl\n");
  const MtlMaterial& m = lib.materials[0];
  CHECK(*m.kd == Vec3{0.5, 0.5, 0.5});
  CHECK_FALSE(m.ks);
  CHECK_FALSE(m.ke);
  CHECK(*m.dissolve == 0.5);
  CHECK(lib.warnings == std::vector<std::string>{ignored("3:4", "Kd spectral"), ignored("4:4", "Ks xyz"),
                                                 ignored("5:4", "Ke spectral"), ignored("6:4", "Kd xyz"),
                                                 ignored("8:3", "d -halo"), ignored("9:4", "Tr -halo"),
                                                 ignored("10:4", "Ks spectral")});
}

TEST_CASE("a repeated material name: find gives the last one, with a warning at each repeat",
          "[scene][mtl]") {
  const MtlLibrary lib = read("newmtl x\nKd 1 0 0\nnewmtl y\nnewmtl x\nKd 0 1 0\nnewmtl x\n  Ks 1\n");
  REQUIRE(lib.materials.size() == 4);
  CHECK(lib.find("x") == &lib.materials[3]);
  CHECK(lib.find("y") == &lib.materials[1]);
  CHECK(lib.find("z") == nullptr);
  CHECK(lib.find("") == nullptr);
  CHECK_FALSE(lib.find("x")->kd);  // a redefinition starts empty
  CHECK(*lib.materials[2].kd == Vec3{0, 1, 0});
  CHECK(lib.warnings ==
        std::vector<std::string>{
            "lib.mtl:4:8: warning: material 'x' is defined again (first at line 1); this later definition counts",
            "lib.mtl:6:8: warning: material 'x' is defined again (first at line 1); this later definition counts"});
  CHECK(MtlLibrary{}.find("x") == nullptr);
}

TEST_CASE("each name's last definition is indexed, so that finding a name is one look-up", "[scene][mtl]") {
  std::string text;
  for (int i = 0; i < 1000; ++i) text += "newmtl m" + std::to_string(i) + "\n";
  text += "newmtl m7\nnewmtl m500\n";
  const MtlLibrary lib = read(text);
  REQUIRE(lib.materials.size() == 1002);
  CHECK(lib.last_definition.size() == 1000);
  CHECK(lib.last_definition.at("m0") == 0);
  CHECK(lib.last_definition.at("m999") == 999);
  CHECK(lib.last_definition.at("m7") == 1000);
  CHECK(lib.last_definition.at("m500") == 1001);
  for (const auto& [name, index] : lib.last_definition) {
    CHECK(lib.materials.at(index).name == name);
    CHECK(lib.find(name) == &lib.materials[index]);
  }
}

TEST_CASE("statements outside a material and nameless materials are errors", "[scene][mtl][errors]") {
  check_refused("Kd 1 1 1\nnewmtl a\n", "lib.mtl:1:1", "'Kd' before the first newmtl");
  check_refused("# header\n\n   Ka 1 1 1\n", "lib.mtl:3:4", "'Ka' before the first newmtl");
  check_refused("map_Kd a.png\n", "lib.mtl:1:1", "before the first newmtl");
  check_refused("newmtl\n", "lib.mtl:1:7", "newmtl needs a material name");
  check_refused("newmtl a\nnewmtl    # no name\n", "lib.mtl:2:7", "newmtl needs a material name");
  check_refused("newmtl \t \r\n", "lib.mtl:1:7", "newmtl needs a material name");
}

TEST_CASE("a missing or an extra number is an error at its place", "[scene][mtl][errors]") {
  check_refused("newmtl a\nKd\n", "lib.mtl:2:3", "Kd: a number is missing");
  check_refused("newmtl a\nKd 1 1\n", "lib.mtl:2:7", "Kd: a number is missing");
  check_refused("newmtl a\nKs 1 1   # two\n", "lib.mtl:2:7", "Ks: a number is missing");
  check_refused("newmtl a\nNs\n", "lib.mtl:2:3", "Ns: a number is missing");
  check_refused("newmtl a\nNi\n", "lib.mtl:2:3", "Ni: a number is missing");
  check_refused("newmtl a\nd\n", "lib.mtl:2:2", "d: a number is missing");
  check_refused("newmtl a\nTr\n", "lib.mtl:2:3", "Tr: a number is missing");
  check_refused("newmtl a\nillum \n", "lib.mtl:2:6", "illum: a number is missing");
  check_refused("newmtl a\nKd 1 1 1 1\n", "lib.mtl:2:10", "unexpected '1' after Kd");
  check_refused("newmtl a\nKe 1 1 1 glow\n", "lib.mtl:2:10", "unexpected 'glow' after Ke");
  check_refused("newmtl a\nNs 1 2\n", "lib.mtl:2:6", "unexpected '2' after Ns");
  check_refused("newmtl a\nNi 1.5 x\n", "lib.mtl:2:8", "unexpected 'x' after Ni");
  check_refused("newmtl a\nd 1 0\n", "lib.mtl:2:5", "unexpected '0' after d");
  check_refused("newmtl a\nTr 0 0\n", "lib.mtl:2:6", "unexpected '0' after Tr");
  check_refused("newmtl a\nillum 2 3\n", "lib.mtl:2:9", "unexpected '3' after illum");
}

TEST_CASE("a malformed number is an error at its word", "[scene][mtl][errors]") {
  check_refused("newmtl a\nKd 1 x 1\n", "lib.mtl:2:6", "Kd: expected a number, found 'x'");
  check_refused("newmtl a\nKd 0,5 0 0\n", "lib.mtl:2:4", "found '0,5'");
  check_refused("newmtl a\nNs 0x10\n", "lib.mtl:2:4", "found '0x10'");
  check_refused("newmtl a\nNi 1.5.2\n", "lib.mtl:2:4", "found '1.5.2'");
  check_refused("newmtl a\nKd nan 0 0\n", "lib.mtl:2:4", "'nan' is not a finite number");
  check_refused("newmtl a\nKs 0 -inf 0\n", "lib.mtl:2:6", "'-inf' is not a finite number");
  check_refused("newmtl a\nNs 1e999\n", "lib.mtl:2:4", "Ns: '1e999' is out of the range of a double");
  check_refused("newmtl a\nKe 1e13 0 0\n", "lib.mtl:2:4", "'1e13' is too large");
  check_refused("newmtl a\nillum two\n", "lib.mtl:2:7", "illum: expected a number, found 'two'");
}

TEST_CASE("a number out of its statement's range is an error at its word", "[scene][mtl][errors]") {
  check_refused("newmtl a\nKd -1 0 0\n", "lib.mtl:2:4", "Kd must be in [0, 1e12], found '-1'");
  check_refused("newmtl a\nKs 0 0 -0.1\n", "lib.mtl:2:8", "Ks must be in [0, 1e12]");
  check_refused("newmtl a\nKe -2\n", "lib.mtl:2:4", "Ke must be in [0, 1e12]");
  check_refused("newmtl a\nNs -1\n", "lib.mtl:2:4", "Ns must be in [0, 1e12]");
  check_refused("newmtl a\nNi 0\n", "lib.mtl:2:4", "Ni must be in (0, 1e12], found '0'");
  check_refused("newmtl a\nNi -1.5\n", "lib.mtl:2:4", "Ni must be in (0, 1e12]");
  check_refused("newmtl a\nd 1.5\n", "lib.mtl:2:3", "d must be in [0, 1], found '1.5'");
  check_refused("newmtl a\nd -0.01\n", "lib.mtl:2:3", "d must be in [0, 1]");
  check_refused("newmtl a\nTr 1.01\n", "lib.mtl:2:4", "Tr must be in [0, 1]");
  check_refused("newmtl a\nillum 11\n", "lib.mtl:2:7", "illum must be in [0, 10], found '11'");
  check_refused("newmtl a\nillum -1\n", "lib.mtl:2:7", "illum must be in [0, 10]");
  check_refused("newmtl a\nillum 2.5\n", "lib.mtl:2:7", "illum is a whole number, found '2.5'");
}

TEST_CASE("a map without a file name is an error past its last word", "[scene][mtl][errors]") {
  check_refused("newmtl a\nmap_Kd\n", "lib.mtl:2:7", "map_Kd needs a file name");
  check_refused("newmtl a\nmap_Ks    # none\n", "lib.mtl:2:7", "map_Ks needs a file name");
  check_refused("newmtl a\nbump\r\n", "lib.mtl:2:5", "bump needs a file name");
  check_refused("newmtl a\nmap_bump -bm 2 -clamp on\n", "lib.mtl:2:25",
                "map_bump needs a file name after its options (-clamp needs on or off)");
}

TEST_CASE("a map option short of its values is an error", "[scene][mtl][errors]") {
  // Only the file name is left: the place is past it.
  check_refused("newmtl a\nmap_Kd -clamp a.png\n", "lib.mtl:2:20",
                "map_Kd needs a file name after its options (-clamp needs on or off)");
  check_refused("newmtl a\nmap_Kd -s a.png\n", "lib.mtl:2:16",
                "map_Kd needs a file name after its options (-s needs 1 value, up to 3)");
  check_refused("newmtl a\nmap_Kd -mm 1 a.png\n", "lib.mtl:2:19", "(-mm needs 2 values)");
  check_refused("newmtl a\nmap_Kd -o\n", "lib.mtl:2:10", "map_Kd needs a file name after its options");
  // A word that is no value: the place is at it.
  check_refused("newmtl a\nmap_Kd -s x a.png\n", "lib.mtl:2:11", "-s needs 1 value, up to 3, found 'x'");
  check_refused("newmtl a\nmap_Kd -s 0 0 a.png\n", "lib.mtl:2:11", "map_Kd -s: a texture's scale must not be 0");
  check_refused("newmtl a\nmap_Ks -s 2 -0 a.png\n", "lib.mtl:2:13", "map_Ks -s: a texture's scale must not be 0");
  check_refused("newmtl a\nmap_Kd -o -s 2 a.png\n", "lib.mtl:2:11", "-o needs 1 value, up to 3, found '-s'");
  check_refused("newmtl a\nmap_Kd -mm 1 x a.png\n", "lib.mtl:2:14", "-mm needs 2 values, found 'x'");
  check_refused("newmtl a\nbump -bm x n.png\n", "lib.mtl:2:10", "-bm needs 1 value, found 'x'");
  check_refused("newmtl a\nmap_Kd -clamp maybe a.png\n", "lib.mtl:2:15", "-clamp needs on or off, found 'maybe'");
  check_refused("newmtl a\nmap_Kd -clamp ON a.png\n", "lib.mtl:2:15", "found 'ON'");
  check_refused("newmtl a\nmap_Kd -clamp -s 2 a.png\n", "lib.mtl:2:15", "found '-s'");
  check_refused("newmtl a\nmap_Kd -blendu 1 a.png\n", "lib.mtl:2:16", "-blendu needs on or off");
  check_refused("newmtl a\nmap_Kd -cc yes a.png\n", "lib.mtl:2:12", "-cc needs on or off");
  check_refused("newmtl a\nmap_Kd -imfchan q a.png\n", "lib.mtl:2:17", "-imfchan needs r, g, b, m, l or z, found 'q'");
  // A value spelt as a number must be a usable one.
  check_refused("newmtl a\nmap_Kd -s 1e999 a.png\n", "lib.mtl:2:11", "map_Kd -s: '1e999' is out of the range");
  check_refused("newmtl a\nmap_Kd -o 1 nan a.png\n", "lib.mtl:2:13", "'nan' is not a finite number");
  check_refused("newmtl a\nmap_Kd -texres 1e20 a.png\n", "lib.mtl:2:16", "'1e20' is too large");
}

TEST_CASE("an unknown map option and -bm off a bump map are errors at the option", "[scene][mtl][errors]") {
  check_refused("newmtl a\nmap_Kd -zoom 2 a.png\n", "lib.mtl:2:8", "unknown option '-zoom' of map_Kd");
  check_refused("newmtl a\nmap_Kd -s 1 -type sphere a.png\n", "lib.mtl:2:13", "unknown option '-type'");
  check_refused("newmtl a\nmap_Ks --clamp on a.png\n", "lib.mtl:2:8", "unknown option '--clamp' of map_Ks");
  check_refused("newmtl a\nmap_Kd -Clamp on a.png\n", "lib.mtl:2:8", "unknown option '-Clamp'");
  check_refused("newmtl a\nmap_Kd -a.png\n", "lib.mtl:2:8", "unknown option '-a.png'");
  check_refused("newmtl a\nmap_Kd -bm 2 a.png\n", "lib.mtl:2:8", "-bm belongs to bump maps, not map_Kd");
  check_refused("newmtl a\nmap_Ks -bm 2 a.png\n", "lib.mtl:2:8", "-bm belongs to bump maps, not map_Ks");
  // The statements clrt ignores are not checked, options and all.
  CHECK_NOTHROW(read("newmtl a\nmap_d -zoom 2 -bm x\n"));
}

TEST_CASE("an error on a later line counts every earlier line, CRLF and blank ones too", "[scene][mtl][errors]") {
  check_refused("# c\r\n\r\nnewmtl a\r\n\r\nKd 1 1\r\n", "lib.mtl:5:7", "missing");
  check_refused(std::string(1000, '\n') + "newmtl a\n\tNs x\n", "lib.mtl:1002:5", "Ns");
}

TEST_CASE("hostile MTL text is read or refused, never a crash or a hang", "[scene][mtl][errors]") {
  // NUL bytes are ordinary bytes of a word.
  const std::string nul_name("newmtl a\0b\nKd 1 1 1\n", 20);
  CHECK(read(nul_name).materials[0].name == std::string("a\0b", 3));
  check_refused(std::string("newmtl a\nKd 1\0 1 1\n", 19), "lib.mtl:2:4", "expected a number");
  CHECK(read("newmtl a\n" + std::string(3, '\0')).warnings.size() == 1);  // an odd keyword
  check_refused(std::string(1, '\0') + " 1\nnewmtl a\n", "lib.mtl:1:1", "before the first newmtl");

  // A huge word is quoted only in part.
  const std::string long_number(1 << 20, '7');
  try {
    read("newmtl a\nNs " + long_number + "x\n");
    FAIL("no error");
  } catch (const SceneError& e) {
    CHECK(e.where().column == 4);
    CHECK(e.message().size() < 200);
  }
  const std::string long_keyword(1 << 20, 'K');
  const MtlLibrary odd = read("newmtl a\n" + long_keyword + " 1\n" + long_keyword + "\n");
  REQUIRE(odd.warnings.size() == 1);
  CHECK(odd.warnings[0].size() < 200);

  // Huge and tiny numbers.
  CHECK(*only_material("Ns 1e12\n").ns == 1e12);
  CHECK(*only_material("Ns 1e-300\n").ns == 1e-300);
  check_refused("newmtl a\nNs 1e-400\n", "lib.mtl:2:4", "out of the range");
  check_refused("newmtl a\nNs " + std::string(400, '9') + "\n", "lib.mtl:2:4", "out of the range");
  check_refused("newmtl a\nillum 99999999999999999999\n", "lib.mtl:2:7", "too large");

  // Long lines: many words, many blanks, many options, a long name.
  std::string many_numbers = "newmtl a\nKd";
  for (int i = 0; i < 200000; ++i) many_numbers += " 1";
  check_refused(many_numbers, "lib.mtl:2:10", "unexpected '1' after Kd");
  const MtlMaterial spaced = only_material("Kd" + std::string(1 << 20, ' ') + "0.5\n");
  CHECK(*spaced.kd == Vec3{0.5, 0.5, 0.5});
  std::string many_options = "map_Kd";
  for (int i = 0; i < 100000; ++i) many_options += " -s 2 3 -clamp on";
  CHECK(only_map(many_options + " x.png").scale == Vec3{2, 3, 1});
  const std::string long_name(1 << 20, 'n');
  CHECK(read("newmtl " + long_name + "\n").find(long_name) != nullptr);

  // Many lines and many materials.
  std::string many;
  for (int i = 0; i < 20000; ++i) many += "newmtl m" + std::to_string(i) + "\nKd 1 1 1\nKa 0 0 0\n";
  const MtlLibrary big = read(many);
  CHECK(big.materials.size() == 20000);
  CHECK(big.warnings.size() == 1);
  CHECK(big.find("m19999") == &big.materials.back());

  // Line ends alone, and a lone CR, which is a blank and not a line end.
  CHECK(read(std::string(100000, '\n')).materials.empty());
  CHECK(read(std::string(100000, '\r')).materials.empty());
  CHECK(read("newmtl a\rb\n").materials[0].name == "a\rb");
}

TEST_CASE("random MTL-like text is read or refused with a SceneError", "[scene][mtl][errors]") {
  const std::vector<std::string> words = {
      "newmtl", "Kd", "Ks", "Ke", "Ns", "Ni", "d", "Tr", "illum", "map_Kd", "map_Ks", "map_bump",
      "bump", "Ka", "-clamp", "-s", "-o", "-bm", "-mm", "-imfchan", "-blendu", "on", "off", "r",
      "spectral", "xyz", "-halo", "0", "1", "-1", "0.5", "2.5", "1e999", "nan", "x.png", "#", "\\",
      " ", "\t", "\r", std::string(1, '\0'), "\xff", "\n"};
  std::uint32_t state = 12345;
  const auto next = [&state] {
    state = state * 1664525u + 1013904223u;
    return state >> 8;
  };
  int read_ok = 0;
  for (int round = 0; round < 3000; ++round) {
    std::string text = round % 2 == 0 ? "newmtl r\n" : "";
    const int count = static_cast<int>(next() % 40);
    for (int i = 0; i < count; ++i) {
      text += words[next() % words.size()];
      if (next() % 2 == 0) text += ' ';
    }
    try {
      read(text);
      ++read_ok;
    } catch (const SceneError& e) {
      CHECK(e.where().line >= 1);
      CHECK(e.where().column >= 1);
    }
  }
  CHECK(read_ok > 0);
}

}  // namespace mtl_reader_test

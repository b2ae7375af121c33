// The OBJ reader on its own: what it accepts, how it cuts polygons, what it refuses and where it
// says the problem is, also when a large file is read in slices on several cores.
#include <catch2/catch.hpp>

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <random>
#include <string>
#include <vector>

#include "math/parallel_for.hpp"
#include "scene/mesh_loader.hpp"
#include "scratch_dir.hpp"

using clrt::MeshData;
using clrt::MeshError;
using clrt::Vec3;
using clrt::test::ScratchDir;

namespace {

using UV = std::array<float, 2>;
using Indices = std::vector<std::uint32_t>;
constexpr std::uint32_t kNone = clrt::kNoMeshTexcoord;

MeshData load_obj_text(const std::string& text) {
  ScratchDir dir;
  return clrt::load_obj_mesh(dir.write("m.obj", text));
}

// The error loading `text` gives, without the file's path.
std::string obj_error(const std::string& text) {
  ScratchDir dir;
  const std::string path = dir.write("m.obj", text);
  try {
    clrt::load_obj_mesh(path);
  } catch (const MeshError& e) {
    const std::string what = e.what();
    REQUIRE(what.rfind(path, 0) == 0);
    return what.substr(path.size());
  }
  FAIL("expected the OBJ text to be rejected: " << text);
  return {};
}

// Twice the signed area of triangle t seen from +z.
double twice_area_z(const MeshData& m, std::size_t t) {
  const Vec3 a = m.positions[m.corners[3 * t]], b = m.positions[m.corners[3 * t + 1]],
             c = m.positions[m.corners[3 * t + 2]];
  return cross(b - a, c - a).z;
}

}  // namespace

TEST_CASE("OBJ: the spellings of numbers, corners and lines a file may use", "[scene][obj]") {
  const MeshData m = load_obj_text(
      "# comment\r\n"
      "mtllib scene.mtl\r\n"
      "o thing\r\n"
      "v +1 .5 -2e-1 # trailing comment\r\n"
      "v\t1.\t0\t0 1.0\r\n"                     // with a weight
      "v 0 1 0 0.5 0.25 1\r\n"                  // with a colour
      "vt 0.5 0.5\r\nvt 1\r\nvp 0.1 0.2\r\n"  // v left out; parameter coordinates are ignored
      "vn 0 0 1\r\n"
      "g group\r\ns 1\r\nusemtl red\r\n"
      "  f 1/1/1 2/2/1 3//1   \r\n"
      "f 1/1 2/2 3/1\r\n"
      "f -3 -2 -1");  // no line end at the end of the file
  REQUIRE(m.positions.size() == 3);
  CHECK(m.positions[0] == Vec3{1, 0.5, static_cast<double>(-0.2f)});
  CHECK(m.positions[1] == Vec3{1, 0, 0});
  CHECK(m.positions[2] == Vec3{0, 1, 0});
  CHECK(m.corners == std::vector<std::uint32_t>{0, 1, 2, 0, 1, 2, 0, 1, 2});
  // The last two faces name no normals: none are kept.
  CHECK(m.normals.empty());
  CHECK(m.corner_normals.empty());
  // Only the middle face names a texture coordinate at every corner.
  CHECK(m.texcoords == std::vector<UV>{{0.5f, 0.5f}, {1, 0}});
  CHECK(m.corner_texcoords == Indices{kNone, kNone, kNone, 0, 1, 0, kNone, kNone, kNone});
}

TEST_CASE("OBJ: a malformed line is an error at its line and column, never a silent 0", "[scene][obj][errors]") {
  const std::string verts = "v 0 0 0\nv 1 0 0\nv 0 1 0\nvn 0 0 1\n";  // lines 1-4
  struct Bad {
    const char* line;
    const char* message;
  };
  const Bad cases[] = {
      {"v", ":5:2: a vertex is x y z [w] or x y z r g b: found 0 numbers"},
      {"v 1 2", ":5:6: a vertex is x y z [w] or x y z r g b: found 2 numbers"},
      {"v 1 nan 2", ":5:5: 'nan' is not a finite number"},
      {"v 1 2 abc", ":5:7: 'abc' is not a number"},
      {"v inf 1 2", ":5:3: 'inf' is not a finite number"},
      {"v 1 -Infinity 2", ":5:5: '-Infinity' is not a finite number"},
      {"v 1e39 1 2", ":5:3: '1e39' is out of range for single precision"},
      {"v 1 1 1e-50", ":5:7: '1e-50' is out of range for single precision"},
      {"vn 0 1", ":5:7: a normal is x y z: found 2 numbers"},
      {"vn 0 1 0 1", ":5:10: too many numbers for a normal (x y z)"},
      {"f 1 2 3/", ":5:7: bad face corner '3/'"},
      {"f 1 2 3//", ":5:7: bad face corner '3//'"},
      {"f 1 2 3/x", ":5:7: bad face corner '3/x'"},
      {"f 1 2 3/1/1/1", ":5:7: bad face corner '3/1/1/1'"},
      {"f 1 2 --3", ":5:7: bad face corner '--3'"},
      {"f 1 2 3x", ":5:7: bad face corner '3x'"},
      {"f 1 2 3/0", ":5:7: texture coordinate index 0 is not allowed"},
      {"f 1 2 3//0", ":5:7: normal index 0 is not allowed"},
      {"f 1 2 99999999999", ":5:7: vertex index '99999999999' is out of range"},
      {"f 1 2 -99999999999", ":5:7: vertex index '-99999999999' is out of range"},
      {"f 1 2 -2147483648", ":5:7: vertex index '-2147483648' is out of range"},
      {"f 1 2 0x1", ":5:7: bad face corner '0x1'"},
      {"f 1 2 3/0x1", ":5:7: bad face corner '3/0x1'"},
      {"f 1 2 3//0x1", ":5:7: bad face corner '3//0x1'"},
      {"f", ":5:2: a face needs at least 3 corners, found 0"},
      {"vt", ":5:3: a texture coordinate is u [v [w]]: found no number"},
      {"vt 0 0 0 0", ":5:10: too many numbers for a texture coordinate"},
      {"v 1 2 3 4 5", ":5:12: a vertex is x y z [w] or x y z r g b: found 5 numbers"},
      {"v 1 2 3 4 5 6 7", ":5:15: too many numbers for a vertex"},
      {"v 1 2 3#4", ":5:7: '3#4' is not a number"},
      {"v 1 2 +-3", ":5:7: '+-3' is not a number"},
      {"v 1 2 0x10", ":5:7: '0x10' is not a number"},
  };
  for (const Bad& c : cases)
    DYNAMIC_SECTION(c.line) { CHECK_THAT(obj_error(verts + c.line + "\nf 1 2 3\n"), Catch::Contains(c.message)); }
}

TEST_CASE("OBJ: a UTF-8 byte order mark at the file's start is skipped", "[scene][obj]") {
  const MeshData m = load_obj_text("\xEF\xBB\xBFv 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
  CHECK(m.positions.size() == 3);
  CHECK(obj_error("\xEF\xBB\xBFv 0 0 x\n") == ":1:7: 'x' is not a number");
}

TEST_CASE("OBJ: a long word is quoted in part only", "[scene][obj][errors]") {
  const std::string word(100000, 'x');
  const std::string message = obj_error("v 1 2 " + word + "\n");
  CHECK_THAT(message, Catch::Contains(":1:7: '" + std::string(40, 'x') + "...' is not a number"));
  CHECK(message.size() < 200);
}

TEST_CASE("OBJ: what is not a regular file is refused before it is read", "[scene][obj][errors]") {
  ScratchDir dir;
  const auto error_of = [](const std::string& path) {
    try {
      clrt::load_obj_mesh(path);
    } catch (const MeshError& e) {
      return std::string(e.what());
    }
    return std::string("loaded");
  };
  CHECK(error_of("/dev/zero") == "/dev/zero: cannot be read (it is not a regular file)");
  CHECK(error_of(dir.path().string()) == dir.path().string() + ": cannot be read (it is a folder)");
  CHECK_THAT(error_of(dir.file("gone.obj")), Catch::Contains("gone.obj: cannot be read (No such file"));
  CHECK(error_of(dir.write("empty.obj", "")) == dir.file("empty.obj") + ": the mesh has no triangles");
}

TEST_CASE("OBJ: a quad is cut along its shorter diagonal, corner 0 to 2 only if strictly shorter",
          "[scene][obj]") {
  // A square: both diagonals are as long.
  CHECK(load_obj_text("v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nf 1 2 3 4\n").corners ==
        std::vector<std::uint32_t>{0, 1, 3, 1, 2, 3});
  // Corner 2 pulled towards corner 0: that diagonal is the shorter.
  CHECK(load_obj_text("v 0 0 0\nv 1 0 0\nv 0.4 0.4 0\nv 0 1 0\nf 1 2 3 4\n").corners ==
        std::vector<std::uint32_t>{0, 1, 2, 0, 2, 3});
  // Normals travel with their corners.
  const MeshData n = load_obj_text("v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nvn 0 0 1\nvn 0 0 2\nvn 0 0 3\nvn 0 0 4\n"
                                   "f 1//1 2//2 3//3 4//4\n");
  CHECK(n.corner_normals == std::vector<std::uint32_t>{0, 1, 3, 1, 2, 3});
}

TEST_CASE("OBJ: a concave polygon is cut into triangles inside it, keeping its winding", "[scene][obj]") {
  // An L, counter-clockwise from +z, starting at the corner of its notch: the fan from there
  // would cover the notch with a clockwise triangle.
  const MeshData m =
      load_obj_text("v 2 1 0\nv 1 1 0\nv 1 2 0\nv 0 2 0\nv 0 0 0\nv 2 0 0\nf 1 2 3 4 5 6\n");
  REQUIRE(m.corners.size() == 12);
  double area = 0;
  for (std::size_t t = 0; t < 4; ++t) {
    INFO("triangle " << t);
    CHECK(twice_area_z(m, t) > 0);
    area += twice_area_z(m, t) / 2;
  }
  CHECK(area == Approx(3.0));
  // Seen from the other side (clockwise from +z) the triangles keep that winding.
  const MeshData flipped =
      load_obj_text("v 2 1 0\nv 1 1 0\nv 1 2 0\nv 0 2 0\nv 0 0 0\nv 2 0 0\nf 6 5 4 3 2 1\n");
  for (std::size_t t = 0; t < 4; ++t) CHECK(twice_area_z(flipped, t) < 0);
}

TEST_CASE("OBJ: texture coordinates are kept per corner, as written or relative", "[scene][obj][texcoords]") {
  const MeshData m = load_obj_text(
      "v 0 0 0\nv 1 0 0\nv 0 1 0\nvn 0 0 1\n"
      "vt 0.1 0.3\nvt 0.7\nvt -2.5 1e3 0.125\n"  // v left out; w read, then dropped
      "f 1/1 2/2 3/3\n"
      "f 1/3/1 2/1/1 3/2/1\n"
      "f 1/-3 2/-1 3/-2\n");
  CHECK(m.texcoords == std::vector<UV>{{0.1f, 0.3f}, {0.7f, 0}, {-2.5f, 1000}});
  CHECK(m.corner_texcoords == Indices{0, 1, 2, 2, 0, 1, 0, 2, 1});
  CHECK(m.corners == Indices{0, 1, 2, 0, 1, 2, 0, 1, 2});
  CHECK(m.normals.empty());  // the first face names none
}

TEST_CASE("OBJ: texture coordinates that no face corner names are not kept", "[scene][obj][texcoords]") {
  const MeshData m = load_obj_text("vt 0 0\nvt 1 0\nvt 0 1\nv 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\nf -3 -2 -1\n");
  CHECK(m.corners.size() == 6);
  CHECK(m.texcoords.empty());
  CHECK(m.corner_texcoords.empty());
}

TEST_CASE("OBJ: a triangle with a corner naming no texture coordinate has none at any corner",
          "[scene][obj][texcoords]") {
  const std::string verts = "v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nvt 1 0\nvt 0 1\n";
  const MeshData m = load_obj_text(verts + "f 1/1 2 3/3\nf 1/1 2/2 3/3\nf 1//1 2/2 3/3\nvn 0 0 1\n");
  CHECK(m.corner_texcoords == Indices{kNone, kNone, kNone, 0, 1, 2, kNone, kNone, kNone});
  CHECK(m.texcoords.size() == 3);
  // When no triangle keeps them, the mesh holds none.
  const MeshData none = load_obj_text(verts + "f 1/1 2 3/3\nf 1/1 2/2 3\n");
  CHECK(none.texcoords.empty());
  CHECK(none.corner_texcoords.empty());
}

TEST_CASE("OBJ: a polygon's texture coordinates follow its corners as it is cut", "[scene][obj][texcoords]") {
  // A square, cut from corner 1 to 3; texture coordinate k named at position k, so that each
  // triangle corner's index into both must match.
  const std::string uv = "vt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\n";
  const MeshData quad = load_obj_text("v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\n" + uv + "f 1/1 2/2 3/3 4/4\n");
  CHECK(quad.corners == Indices{0, 1, 3, 1, 2, 3});
  CHECK(quad.corner_texcoords == quad.corners);
  // The concave L of the test above, ear-clipped.
  const MeshData l = load_obj_text("v 2 1 0\nv 1 1 0\nv 1 2 0\nv 0 2 0\nv 0 0 0\nv 2 0 0\n" + uv +
                                   "vt 2 2\nvt 3 3\nf 1/1/1 2/2/1 3/3/1 4/4/1 5/5/1 6/6/1\nvn 0 0 1\n");
  REQUIRE(l.corners.size() == 12);
  CHECK(l.corners != Indices({0, 1, 2, 0, 2, 3, 0, 3, 4, 0, 4, 5}));  // not the fan
  CHECK(l.corner_texcoords == l.corners);
  CHECK(l.corner_normals == Indices(12, 0));
  // A corner without one: each triangle cut with it loses them, whether or not the fan's did.
  const std::string partial = uv + "f 1/1 2/2 3/3 4\n";
  const MeshData square = load_obj_text("v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\n" + partial);
  CHECK(square.corners == Indices{0, 1, 3, 1, 2, 3});
  CHECK(square.corner_texcoords.empty());  // the fan's (0, 1, 2) had them, but it was cut otherwise
  const MeshData kite = load_obj_text("v 0 0 0\nv 1 0 0\nv 0.4 0.4 0\nv 0 1 0\n" + partial);
  CHECK(kite.corners == Indices{0, 1, 2, 0, 2, 3});
  CHECK(kite.corner_texcoords == Indices{0, 1, 2, kNone, kNone, kNone});
}

TEST_CASE("OBJ: a texture coordinate index out of range is an error at its corner",
          "[scene][obj][texcoords][errors]") {
  const std::string verts = "v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nvt 1 0\n";  // lines 1-5
  CHECK(obj_error(verts + "f 1/1 2/2 3/3\n") == ":6:11: texture coordinate index 3 is out of range (the file has 2)");
  CHECK(obj_error(verts + "f 1/1 2/-3 3/1\n") ==
        ":6:7: relative texture coordinate index -3 reaches before the first one");
  // Also in a triangle that would not keep them, and in a file with no other corner naming one.
  CHECK(obj_error(verts + "f 1 2 3/9\n") == ":6:7: texture coordinate index 9 is out of range (the file has 2)");
  CHECK(obj_error("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1/1/1 2//1 3//1\nvn 0 0 1\n") ==
        ":4:3: texture coordinate index 1 is out of range (the file has 0)");
  // A bad vertex index is reported before a bad texture coordinate index of the same corner.
  CHECK(obj_error(verts + "f 1/1 2/2 4/3\n") == ":6:11: vertex index 4 is out of range (the file has 3)");
}

namespace {

// One face of `corners` corners round the origin in z = 0, counter-clockwise: a circle of radius
// 1000, or a star whose every second corner lies at radius 600.
std::string round_face_obj(int corners, bool star) {
  std::string text, face = "f";
  for (int i = 0; i < corners; ++i) {
    const double angle = 2 * 3.14159265358979 * i / corners, r = star && i % 2 ? 600 : 1000;
    text += "v " + std::to_string(r * std::cos(angle)) + " " + std::to_string(r * std::sin(angle)) + " 0\n";
    face += " " + std::to_string(i + 1);
  }
  return text + face + "\n";
}

}  // namespace

TEST_CASE("OBJ: a convex face beyond the concave corner limit is its fan, covering it exactly",
          "[scene][obj][polygons]") {
  const int corners = 6000;  // many more would not stay convex once rounded to single precision
  const MeshData m = load_obj_text(round_face_obj(corners, false));
  REQUIRE(m.corners.size() == 3 * (corners - 2));
  double area = 0;
  bool all_counter_clockwise = true;
  for (std::size_t t = 0; t < corners - 2; ++t) {
    all_counter_clockwise = all_counter_clockwise && twice_area_z(m, t) > 0;
    area += twice_area_z(m, t) / 2;
  }
  CHECK(all_counter_clockwise);
  CHECK(area == Approx(3.14159265358979e6).epsilon(1e-6));
}

TEST_CASE("OBJ: a concave face beyond the corner limit is refused at its line",
          "[scene][obj][polygons][errors]") {
  CHECK(obj_error(round_face_obj(200000, true)) ==
        ":200001:1: a concave polygon of 200000 corners: clrt cuts concave polygons of at most 4096 "
        "corners (convex ones of any size)");
}

namespace {

// A strip of `quads` unit quads along x as an OBJ file of about 50 bytes a quad: vertices 2k
// (bottom) and 2k + 1 (top); every second face written with relative indices, and the first
// face naming vertices that come only at the end of the file.
std::string strip_obj(int quads) {
  std::string text = "f 1 " + std::to_string(2 * quads + 1) + " 2\n";  // a forward reference to the last vertex
  for (int k = 0; k <= quads; ++k) {
    text += "v " + std::to_string(k) + " 0 0\nv " + std::to_string(k) + " 1 0\n";
    if (k == 0) continue;
    const int a = 2 * k - 1, b = 2 * k, c = 2 * k + 1, d = 2 * k + 2;  // from 1
    if (k % 2) text += "f " + std::to_string(a) + " " + std::to_string(c) + " " + std::to_string(d) + " " + std::to_string(b) + "\n";
    else text += "f -4 -2 -1 -3\n";
  }
  return text;
}

}  // namespace

TEST_CASE("OBJ: a file read in slices gives what one pass gives, and the first error in the file",
          "[scene][obj]") {
  const int quads = 80000;  // about 3.5 MB: several slices however many cores
  const std::string text = strip_obj(quads);
  REQUIRE(text.size() > 3u << 20);
  const MeshData m = load_obj_text(text);
  for (unsigned threads : {1u, 3u}) {
    clrt::parallel_thread_limit = threads;
    const MeshData other = load_obj_text(text);
    clrt::parallel_thread_limit = 0;
    INFO(threads << " threads");
    CHECK(other.positions == m.positions);
    CHECK(other.corners == m.corners);
  }
  REQUIRE(m.positions.size() == 2 * static_cast<std::size_t>(quads) + 2);
  REQUIRE(m.corners.size() == 3 + 6 * static_cast<std::size_t>(quads));
  CHECK(std::vector<std::uint32_t>(m.corners.begin(), m.corners.begin() + 3) ==
        std::vector<std::uint32_t>{0, 2 * static_cast<std::uint32_t>(quads), 1});
  for (int k = 1; k <= quads; ++k) {
    // Each quad's corners, from 0: (2k - 2, 2k, 2k + 1, 2k - 1), cut along a diagonal.
    const std::uint32_t* c = &m.corners[3 + 6 * static_cast<std::size_t>(k - 1)];
    const std::uint32_t a = 2 * k - 2, b = 2 * k - 1, d = 2 * k + 1;
    INFO("quad " << k);
    REQUIRE(m.positions[a] == Vec3{k - 1.0, 0, 0});
    // A unit square: cut from corner 0 = a to corner 3 = b.
    CHECK(c[0] == a);
    CHECK(c[2] == b);
    CHECK(c[4] == d);
    CHECK(c[5] == b);
  }

  // Lines counted across slices: errors near the end of the file, found by a later slice.
  const std::size_t lines = static_cast<std::size_t>(std::count(text.begin(), text.end(), '\n'));
  CHECK_THAT(obj_error(text + "f 1 2 x\n"), Catch::Contains(":" + std::to_string(lines + 1) + ":7: bad face corner 'x'"));
  CHECK_THAT(obj_error(text + "f 1 2 999999\n"),
             Catch::Contains(":" + std::to_string(lines + 1) + ":7: vertex index 999999 is out of range"));
  // Of two malformed lines the first one in the file is reported, though a later slice found the
  // other first.
  CHECK_THAT(obj_error("v 1 2 x\n" + text + "v nan 0 0\n"), Catch::Contains(":1:7: 'x' is not a number"));
  // A malformed line is reported before an index out of range earlier in the file.
  CHECK_THAT(obj_error("f 1 2 999999\n" + text + "v nan 0 0\n"),
             Catch::Contains(":" + std::to_string(lines + 2) + ":3: 'nan' is not a finite number"));
}

TEST_CASE("OBJ: texture coordinates read in slices: slices naming none, relative indices across them",
          "[scene][obj][texcoords]") {
  const int quads = 80000;
  // Texture coordinates at the start, named only by the last face, from a later slice.
  const std::string text = "vt 0.25 0.75\nvt 1 0\nvt 0 1\n" + strip_obj(quads) + "f 1/-3 2/-1 3/-2\n";
  REQUIRE(text.size() > 3u << 20);
  const MeshData m = load_obj_text(text);
  const std::size_t corners = 6 + 6 * static_cast<std::size_t>(quads);
  REQUIRE(m.corners.size() == corners);
  CHECK(m.texcoords == std::vector<UV>{{0.25f, 0.75f}, {1, 0}, {0, 1}});
  Indices expected(corners, kNone);
  expected[corners - 3] = 0;
  expected[corners - 2] = 2;
  expected[corners - 1] = 1;
  CHECK(m.corner_texcoords == expected);
  for (unsigned threads : {1u, 3u}) {
    clrt::parallel_thread_limit = threads;
    const MeshData other = load_obj_text(text);
    clrt::parallel_thread_limit = 0;
    INFO(threads << " threads");
    CHECK(other.texcoords == m.texcoords);
    CHECK(other.corner_texcoords == m.corner_texcoords);
  }
  const std::size_t lines = static_cast<std::size_t>(std::count(text.begin(), text.end(), '\n'));
  CHECK_THAT(obj_error(text + "f 1/1 2/2 3/4\n"),
             Catch::Contains(":" + std::to_string(lines + 1) + ":11: texture coordinate index 4 is out of range (the file has 3)"));
}

TEST_CASE("OBJ: numbers read exactly as std::from_chars reads them, in every spelling", "[scene][obj]") {
  // Random decimals of 1 to 12 digits, the point anywhere, some with exponents: the short ones
  // take the reader's quick path, the others std::from_chars.
  std::mt19937 rng(11);
  std::string text;
  std::vector<float> expected;
  for (int i = 0; i < 30000; ++i) {
    std::string digits;
    const int count = 1 + static_cast<int>(rng() % 12);
    for (int d = 0; d < count; ++d) digits += static_cast<char>('0' + rng() % 10);
    const std::size_t point = rng() % (digits.size() + 1);
    std::string word = (rng() % 2 ? "-" : "") + digits.substr(0, point) + "." + digits.substr(point);
    if (word == "." || word == "-.") word += "0";
    if (rng() % 8 == 0) word += "e" + std::to_string(static_cast<int>(rng() % 20) - 10);
    float value = 0;
    const auto result = std::from_chars(word.data(), word.data() + word.size(), value);
    REQUIRE(result.ec == std::errc());
    text += "v " + word + " 0 0\n";
    expected.push_back(value);
  }
  text += "f 1 2 3\n";
  const MeshData m = load_obj_text(text);
  REQUIRE(m.positions.size() == expected.size());
  std::size_t differ = 0;
  for (std::size_t i = 0; i < expected.size(); ++i) differ += m.positions[i].x != static_cast<double>(expected[i]);
  CHECK(differ == 0);
}

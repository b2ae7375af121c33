// clrt --dump-scene through the executable: where the JSON goes, the exit codes, and outputs it
// must not replace or leave half written; textures and texture coordinates, which need image and
// OBJ files beside the scene. The rest of what the document holds: tests/scene/scene_json_test.cpp.
#include <catch2/catch.hpp>

#include <sys/stat.h>

#include <filesystem>
#include <nlohmann/json.hpp>
#include <regex>
#include <string>
#include <thread>

#include "render_support.hpp"
#include "scratch_dir.hpp"

using namespace clrt::test;
namespace fs = std::filesystem;
using Json = nlohmann::json;

namespace {

const char* const kScene = "eye 0 0 5\nlight 1 1 1 point 0 3 3\nsphere\ntranslate 0 -1 0\nplane\n";

std::string dump_to(const std::string& out, const std::string& scene) {
  return "--dump-scene " + quoted(out) + " " + quoted(scene);
}

// Plain PPM (sRGB) and PFM (linear) images of 2x1 texels.
const char* const kPpm = "P3\n2 1\n255\n255 0 0  0 0 255\n";
const std::string kPfm = std::string("PF\n2 1\n-1.0\n") + std::string(24, '\0');

// One texture of every kind, on every term; a triangle with (u, v) and one without.
const char* const kTextured =
    "material 1 1 1  0 1 0.5 8  0.25 0\n"
    "texture color image red_blue.ppm wrap clamp scale 2 -3 offset 0.5 -0.25\n"
    "texture kr checker 1 0 0  0 0 1\n"
    "triangle 0 0 0 0.25 0.5  1 0 0 0.75 0.5  0 1 0 0.5 1\n"
    "texture ks noise 0 0 0  1 1 1 octaves 3 scale 4 4\n"
    "texture kt image dark.pfm\n"
    "triangle 0 0 0  1 0 0  0 1 0\n";

// A scene whose dump is far larger than one block of `ulimit -f`.
std::string many_spheres() {
  std::string text;
  for (int i = 0; i < 100; ++i) text += "sphere " + std::to_string(i) + " 0 0 0.5\n";
  return text;
}

}  // namespace

TEST_CASE("clrt --dump-scene - writes the scene as JSON to standard output, without OpenCL",
          "[cli][dump]") {
  ScratchDir dir;
  const std::string scene = dir.write("s.ray", kScene);
  // No OpenCL implementation to be found: a render would exit 1 here.
  const CommandResult r = run_clrt("--dump-scene - " + quoted(scene), "OCL_ICD_VENDORS=" + dir.file("none"));
  INFO(r.output);
  REQUIRE(r.exit_code == 0);
  const Json j = Json::parse(r.output);
  CHECK(j["format"] == "clrt-scene");
  CHECK(j["objects"].size() == 2);
  CHECK(j["lights"][0]["kind"] == "point");
  CHECK(dir.entries() == std::set<std::string>{"s.ray"});
}

TEST_CASE("clrt --dump-scene FILE writes the file, and the command line's settings into it",
          "[cli][dump]") {
  ScratchDir dir;
  const std::string scene = dir.write("s.ray", kScene), out = dir.file("s.json");
  const CommandResult r = run_clrt(dump_to(out, scene) + " --resolution 30x10 --spp 3 --max-depth 7");
  INFO(r.output);
  REQUIRE(r.exit_code == 0);
  CHECK(r.output.empty());
  const Json j = Json::parse(file_bytes(out));
  CHECK(j["resolution"] == Json::array({30, 10}));
  CHECK(j["samples"] == 3);
  CHECK(j["maxdepth"] == 7);
}

TEST_CASE("clrt --dump-scene reads NFF scenes too", "[cli][dump][nff]") {
  ScratchDir dir;
  const std::string scene =
      dir.write("s.nff", "v\nfrom 0 0 5\nat 0 0 0\nup 0 1 0\nangle 45\nhither 0.5\nresolution 8 8\ns 0 0 0 1\n");
  const CommandResult r = run_clrt("--dump-scene - " + quoted(scene));
  INFO(r.output);
  REQUIRE(r.exit_code == 0);
  CHECK(Json::parse(r.output)["objects"][0]["shape"] == "sphere");
}

TEST_CASE("clrt --dump-scene: a scene error exits 2 at its place and writes nothing", "[cli][dump]") {
  ScratchDir dir;
  const std::string scene = dir.write("bad.ray", "sphere\nsphere 1 2\n"), out = dir.file("bad.json");
  const CommandResult r = run_clrt(dump_to(out, scene));
  CHECK(r.exit_code == 2);
  CHECK(std::regex_search(r.output, std::regex("bad\\.ray:2:\\d+: error: ")));
  CHECK(dir.entries() == std::set<std::string>{"bad.ray"});
}

TEST_CASE("clrt --dump-scene: outputs refused before the scene is read exit 2", "[cli][dump]") {
  ScratchDir dir;
  const std::string scene = dir.write("s.ray", kScene);
  for (const std::string& out : {dir.file("no/such/folder.json"), dir.path().string(), scene}) {
    const CommandResult r = run_clrt(dump_to(out, scene));
    INFO(out << ": " << r.output);
    CHECK(r.exit_code == 2);
    CHECK(r.output.find("clrt: error: ") != std::string::npos);
  }
  CHECK(file_bytes(scene) == kScene);
  CHECK(run_clrt("--dump-scene '' " + quoted(scene)).exit_code == 2);
  CHECK(run_clrt("--dump-scene -").exit_code == 2);  // no scene
}

TEST_CASE("clrt --dump-scene: a write that fails leaves the old file whole",
          "[cli][dump]") {
  ScratchDir dir;
  const std::string scene = dir.write("s.ray", many_spheres());
  const CommandResult full = run_clrt(dump_to("/dev/full", scene));
  CHECK(full.exit_code == 1);
  CHECK(full.output.find("/dev/full") != std::string::npos);

  // Past the file size limit, which ends clrt by SIGXFSZ (128 + 25) once its temporary is gone.
  const std::string out = dir.write("s.json", "the old dump");
  const CommandResult limited = run_program(
      "/bin/sh", "-c 'ulimit -f 1; exec \"$0\" \"$@\"' " + quoted(CLRT_EXE) + " " + dump_to(out, scene));
  INFO(limited.output);
  CHECK(limited.exit_code == 153);
  CHECK(file_bytes(out) == "the old dump");
  CHECK(dir.entries() == std::set<std::string>{"s.ray", "s.json"});
}

TEST_CASE("clrt --dump-scene writes through a FIFO and a link, replacing neither", "[cli][dump]") {
  ScratchDir dir;
  const std::string scene = dir.write("s.ray", kScene);
  const std::string fifo = dir.file("fifo.json");
  REQUIRE(::mkfifo(fifo.c_str(), 0600) == 0);
  std::string read_back;
  std::thread reader([&] { read_back = file_bytes(fifo); });
  const CommandResult r = run_clrt(dump_to(fifo, scene));
  reader.join();
  INFO(r.output);
  CHECK(r.exit_code == 0);
  CHECK(fs::is_fifo(fifo));
  CHECK(Json::parse(read_back)["format"] == "clrt-scene");

  const std::string target = dir.write("target.json", "old"), link = dir.file("link.json");
  fs::create_symlink("target.json", link);
  REQUIRE(run_clrt(dump_to(link, scene)).exit_code == 0);
  CHECK(fs::is_symlink(link));
  CHECK(Json::parse(file_bytes(target))["format"] == "clrt-scene");
}

TEST_CASE("clrt --dump-scene writes the textures, each material's textured terms and triangles' (u, v)",
          "[cli][dump][texture]") {
  ScratchDir dir;
  dir.write("red_blue.ppm", kPpm);
  dir.write("dark.pfm", kPfm);
  const CommandResult r = run_clrt("--dump-scene - " + quoted(dir.write("s.ray", kTextured)));
  INFO(r.output);
  REQUIRE(r.exit_code == 0);
  const Json j = Json::parse(r.output);
  CHECK(j["version"] == 2);
  const Json& textures = j["textures"];
  REQUIRE(textures.size() == 4);
  CHECK(textures[0] == Json{{"kind", "image"}, {"file", dir.file("red_blue.ppm")}, {"width", 2}, {"height", 1},
                            {"linear", false}, {"wrap", "clamp"}, {"scale", {2.0, -3.0}},
                            {"offset", {0.5, -0.25}}});
  CHECK(textures[1] == Json{{"kind", "checker"}, {"colors", {{1.0, 0.0, 0.0}, {0.0, 0.0, 1.0}}},
                            {"scale", {1.0, 1.0}}, {"offset", {0.0, 0.0}}});
  CHECK(textures[2] == Json{{"kind", "noise"}, {"colors", {{0.0, 0.0, 0.0}, {1.0, 1.0, 1.0}}}, {"octaves", 3},
                            {"scale", {4.0, 4.0}}, {"offset", {0.0, 0.0}}});
  CHECK(textures[3]["linear"] == true);
  CHECK(textures[3]["wrap"] == "repeat");

  // The default, `material`, then a copy per `texture`, each adding its term.
  const Json& materials = j["materials"];
  REQUIRE(materials.size() == 6);
  CHECK(materials[1]["textures"] == Json::object());
  CHECK(materials[3]["textures"] == Json{{"color", 0}, {"kr", 1}});
  CHECK(materials[5]["textures"] == Json{{"color", 0}, {"ks", 2}, {"kr", 1}, {"kt", 3}});
  CHECK(materials[5]["ks"] == 0.5);  // the term itself, as the material gave it

  REQUIRE(j["triangles"].size() == 2);
  CHECK(j["triangles"][0]["material"] == 3);
  CHECK(j["triangles"][0]["uv"] == Json{{0.25, 0.5}, {0.75, 0.5}, {0.5, 1.0}});
  CHECK_FALSE(j["triangles"][1].contains("uv"));
}

TEST_CASE("clrt --dump-scene writes a mesh's texture coordinates, null for a triangle without",
          "[cli][dump][texture]") {
  ScratchDir dir;
  dir.write("vt.obj", "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nvt 0 0\nvt 0.5 0\nvt 0.5 0.25 0.75\n"
                      "f 1/3 2/2 3/1\nf 1 3 4\n");
  dir.write("plain.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
  const CommandResult r = run_clrt("--dump-scene - " + quoted(dir.write("s.ray", "mesh vt.obj\nmesh plain.obj\n")));
  INFO(r.output);
  REQUIRE(r.exit_code == 0);
  const Json meshes = Json::parse(r.output)["meshes"];
  REQUIRE(meshes.size() == 2);
  CHECK(meshes[0]["texcoords"] == Json{{0.0, 0.0}, {0.5, 0.0}, {0.5, 0.25}});  // w dropped
  CHECK(meshes[0]["triangle_texcoords"] == Json{{2, 1, 0}, nullptr});
  CHECK(meshes[1]["texcoords"] == Json::array());
  CHECK(meshes[1]["triangle_texcoords"] == Json::array());
}

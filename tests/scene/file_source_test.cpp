// Loading a scene from files held in memory (an MPI rank that received rank 0's files) gives the
// scene the disk gives, and a file missing from the set is an error at the command naming it.
#include <catch2/catch.hpp>

#include <filesystem>
#include <map>
#include <string>

#include "scene/file_source.hpp"
#include "scene/scene.hpp"
#include "scene_equivalence.hpp"
#include "scratch_dir.hpp"

using namespace clrt;

namespace {

const char* const kScene =
    "resolution 40 30\n"
    "light 1 1 1 point 0 5 5\n"
    "mesh pyramid.obj\n"
    "translate 3 0 0\n"
    "mesh \"pyramid.obj\"\n"
    "sphere 0 0 -2 1\n";

const char* const kPyramid =
    "v 0 1 0\nv -1 0 1\nv 1 0 1\nv 1 0 -1\nv -1 0 -1\n"
    "f 1 2 3\nf 1 3 4\nf 1 4 5\nf 1 5 2\nf 2 5 4 3\n";

}  // namespace

TEST_CASE("a scene read from recorded files equals the scene read from the disk", "[scene][files]") {
  test::ScratchDir dir;
  const std::string scene_path = dir.write("s.ray", kScene);
  dir.write("pyramid.obj", kPyramid);
  RecordingFiles recording;
  const Scene from_disk = load_scene(scene_path, recording);
  REQUIRE(recording.files().size() == 2);  // the scene file and the mesh, read once
  // The copies are what the ranks receive: the disk is no longer needed.
  const MemoryFiles received(recording.files());
  std::filesystem::remove_all(dir.path());
  const Scene from_memory = load_scene(scene_path, received);
  CHECK(test::scene_difference(from_disk, from_memory, 0).empty());
  CHECK(from_memory.meshes.size() == 1);
  CHECK(from_memory.meshes[0].corners.size() == 18);
}

TEST_CASE("a file missing from the set in memory is an error where it is named",
          "[scene][files]") {
  const MemoryFiles only_scene(std::map<std::string, std::string>{{"/nowhere/s.ray", kScene}});
  CHECK_THROWS_WITH(load_scene("/nowhere/s.ray", only_scene),
                    Catch::Contains("s.ray:3:1: error: bad mesh file /nowhere/pyramid.obj") &&
                        Catch::Contains("not among the scene's files"));
  CHECK_THROWS_WITH(load_scene("/nowhere/t.ray", only_scene),
                    Catch::Contains("t.ray: error: cannot read the scene file"));
}

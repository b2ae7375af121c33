// A .ray scene from arbitrary text, taken as far as clrt takes it before the device: the loader,
// the BVH build and the frame set-up. A small OBJ mesh (mesh.obj) lies beside the scene so that
// `mesh` commands reach the instancing paths. A rejected scene is a SceneError; anything else
// escaping, or a sanitizer report, is a finding.
#include <cstddef>
#include <cstdint>

#include "fuzz_input_file.hpp"
#include "geometry/geometry_data.hpp"
#include "render/frame_setup.hpp"
#include "scene/scene.hpp"

namespace {

const char kMesh[] =
    "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\n"
    "vn 0 0 1\nvn 1 0 0\nvn 0 1 0\nvn 0 0 1\n"
    "f 1//1 2//2 3//3\nf 1//1 3//3 4//4\nf 2 3 4 1\n";

}  // namespace

extern "C" int LLVMFuzzerInitialize(int*, char***) {
  clrt::fuzz::write_input("mesh.obj", reinterpret_cast<const std::uint8_t*>(kMesh), sizeof kMesh - 1);
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string path = clrt::fuzz::write_input("scene.ray", data, size);
  clrt::Scene scene;
  try {
    scene = clrt::load_scene(path);
  } catch (const clrt::SceneError&) {
    return 0;
  }
  const clrt::GeometryData geometry = clrt::build_geometry(scene);
  const clrt::FrameData frame = clrt::make_frame(scene, clrt::RenderOptions::from_scene(scene));
  if (geometry.nodes.empty() || frame.materials.empty()) __builtin_trap();
  return 0;
}

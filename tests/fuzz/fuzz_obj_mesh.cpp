// A Wavefront OBJ mesh from arbitrary text through load_obj_mesh(), as a scene's `mesh` command
// reads it. A rejected file is a MeshError; anything else escaping, or a sanitizer report, is a
// finding, and so is an accepted mesh whose indices point outside its tables.
#include <cstddef>
#include <cstdint>

#include "fuzz_input_file.hpp"
#include "scene/mesh_loader.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string path = clrt::fuzz::write_input("mesh.obj", data, size);
  try {
    const clrt::MeshData mesh = clrt::load_obj_mesh(path);
    if (mesh.corners.empty() || mesh.corners.size() % 3 != 0) __builtin_trap();
    for (std::uint32_t corner : mesh.corners)
      if (corner >= mesh.positions.size()) __builtin_trap();
    for (std::uint32_t corner : mesh.corner_normals)
      if (corner >= mesh.normals.size()) __builtin_trap();
  } catch (const clrt::MeshError&) {
  }
  return 0;
}

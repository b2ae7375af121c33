#include "fuzz_paths.hpp"

#include "fuzz_require.hpp"
#include "geometry/geometry_data.hpp"
#include "image/image.hpp"
#include "render/frame_setup.hpp"
#include "scene/mesh_loader.hpp"
#include "scene/scene.hpp"

namespace clrt::fuzz {

Outcome ray_scene(const std::string& path) {
  Scene scene;
  try {
    scene = load_scene(path);
  } catch (const SceneError&) {
    return Outcome::Rejected;
  }
  const GeometryData geometry = build_geometry(scene);
  const FrameData frame = make_frame(scene, geometry, RenderOptions::from_scene(scene));
  require(!geometry.nodes.empty(), "a loaded scene gave no BVH root");
  require(!frame.materials.empty(), "a loaded scene gave no default material");
  return Outcome::Accepted;
}

Outcome obj_mesh(const std::string& path) {
  MeshData mesh;
  try {
    mesh = load_obj_mesh(path);
  } catch (const MeshError&) {
    return Outcome::Rejected;
  }
  require(!mesh.corners.empty() && mesh.corners.size() % 3 == 0, "an accepted mesh has no whole triangles");
  for (std::uint32_t corner : mesh.corners)
    require(corner < mesh.positions.size(), "an accepted mesh has a corner past its vertices");
  for (std::uint32_t corner : mesh.corner_normals)
    require(corner < mesh.normals.size(), "an accepted mesh has a corner past its normals");
  return Outcome::Accepted;
}

Outcome image(const std::string& path) {
  Rgba8Image image;
  try {
    image = read_image(path);
  } catch (const ImageError&) {
    return Outcome::Rejected;
  }
  require(image.width > 0 && image.height > 0 && !image.frames.empty(), "an accepted image is empty");
  for (const auto& frame : image.frames)
    require(frame.size() == 4 * static_cast<std::size_t>(image.width) * static_cast<std::size_t>(image.height),
            "an accepted image's frame does not match its size");
  return Outcome::Accepted;
}

}  // namespace clrt::fuzz

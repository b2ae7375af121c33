// The scene model: everything a scene file (.ray or NFF) describes, validated and ready to upload.
#pragma once

#include <array>
#include <cstdint>
#include <deque>
#include <optional>
#include <string>
#include <vector>

#include "math/mat4.hpp"
#include "math/vec3.hpp"
#include "scene/file_source.hpp"
#include "scene/source_location.hpp"

namespace clrt {

struct CameraSpec {
  Vec3 eye{0, 0, 5};
  Vec3 lookat{0, 0, 0};
  Vec3 up{0, 1, 0};
  double fov_degrees = 60;  // horizontal, across the image width
  // `lens RADIUS FOCUS`: a thin lens of this aperture radius (0: a pinhole), in focus at this
  // distance from the eye along the view direction.
  double lens_radius = 0;
  double focus_distance = 1;
  // `shutter OPEN CLOSE`: camera samples' times are spread over [OPEN, CLOSE]; moving objects
  // have their first pose at time 0 and their second at time 1.
  double shutter_open = 0, shutter_close = 1;
};

struct MaterialSpec {
  Vec3 color{1, 1, 1};
  double ka = 0.2, kd = 0.8, ks = 0, shininess = 1;
  double kr = 0, kt = 0;
  double ior = 1;  // a value <= 0 in the file is stored as 1
  Vec3 emission{0, 0, 0};  // radiance leaving the front side (`emission`)
  // Per CLRT_TEXTURE_SLOT_* (colour, ks, kr, kt): an index into Scene::textures whose value
  // multiplies that term, or -1.
  std::array<int, 4> textures{-1, -1, -1, -1};
};

// An image a texture shows, read once however many textures use it; rows from the top.
struct TextureImage {
  std::string path;  // as resolved
  int width = 0, height = 0;
  bool linear = false;                  // PFM, EXR: `rgb` holds linear values
  std::vector<std::uint8_t> srgb;       // PNG, PPM, FSF: 3 sRGB-encoded bytes per texel (in the decoder's buffer of 4)
  std::vector<float> rgb;               // PFM, EXR: 3 floats per texel
};

// `texture` (docs/scene-format.md#textures), or an MTL map: what a material's term is multiplied by.
struct TextureSpec {
  enum class Kind { Image, Checker, Noise } kind = Kind::Image;
  int image = -1;  // Kind::Image: index into Scene::texture_images
  bool clamp = false;  // images: clamp (s, t) to [0, 1] rather than repeat
  double scale[2] = {1, 1}, offset[2] = {0, 0};  // (s, t) = (u, v) * scale + offset
  Vec3 color0{0, 0, 0}, color1{1, 1, 1};  // checker and noise
  int octaves = 4;  // noise
};

// `environment FILE [SCALE]`: the radiance arriving from every direction, an equirectangular
// image in Mitsuba 3's `envmap` orientation, turned by the rotation in force at the command
// (docs/scene-format.md#environment).
struct EnvironmentSpec {
  std::string path;  // as resolved against the scene's folder
  double scale = 1;
  Mat4 rotation;     // map to world: the current transform's linear part, a rotation
  int width = 0, height = 0;
  std::vector<float> rgb;  // linear radiance before the scale, rows from the top (+y) down
};

// A light as its command gives it. Its kind is the name of its row of light_kind_table()
// (scene/light_kinds.hpp), which reads its parameters into the fields below: the words the kinds
// share (a place, a direction, two edges, an angle, an exponent, a number of samples), so that a
// kind which needs no other word adds nothing here.
struct LightSpec {
  std::string kind = "point";
  Vec3 color;
  Vec3 position;       // point, spot; area: corner
  Vec3 direction;      // directional: direction of travel; spot: axis (as written, not normalised)
  Vec3 edge_u, edge_v; // area
  double angle_degrees = 180;  // spot: cut-off half-angle
  double exponent = 0;         // spot
  int samples = 1;             // area: default 16
};

enum class ShapeKind : std::uint8_t { Sphere, Plane, Cube, Cylinder, Cone, Mesh };

// Where in the scene file (Scene::path) a command was written.
struct TextPlace {
  int line = 1;
  int column = 1;
};

// A scene of millions of spheres holds millions of these, so the record keeps only what cannot
// be derived: M^-1 is computed where it is used (Mat4::inverse gives the same bits every time),
// and the file of its place is the scene's. 168 bytes.
struct InstanceSpec {
  ShapeKind shape = ShapeKind::Sphere;
  // ShapeKind::Mesh: its faces named by `usemtl` take their MTL materials (MeshData::
  // name_materials); the others, and every face when false (`mtl off`), take `material`.
  bool mesh_materials = false;
  int material = 0;  // index into Scene::materials
  int mesh = -1;     // ShapeKind::Mesh: index into Scene::meshes
  TextPlace place;
  int motion = -1;  // -1, or a moving object's index into Scene::end_transforms
  double cone_r0 = 1, cone_r1 = 0;
  Mat4 transform;  // M: object to world (a moving object's pose at time 0)
};

// An instance of `shape` placed by `to_world`.
InstanceSpec place_instance(ShapeKind shape, const Mat4& to_world, int material = 0);

// A place in a mesh file that names something: an `mtllib` library, a `usemtl` material.
struct MeshName {
  std::string name;  // as written
  SourceLocation where;
};

// A triangle mesh in its own object space, loaded once however many instances use it.
struct MeshData {
  std::string path;                  // as resolved against the scene's folder
  std::vector<Vec3> positions;
  std::vector<Vec3> normals;         // empty, or the file's normals (see corner_normals)
  std::vector<std::uint32_t> corners;  // 3 per triangle, into `positions`, counter-clockwise
  std::vector<std::uint32_t> corner_normals;  // 3 per triangle into `normals` when normals exist
  // `vt`: the file's texture coordinates (u, v as single-precision values; a missing v is 0, a w
  // is dropped), and 3 per triangle, indices into them; both empty when no face corner names one.
  // A triangle with a corner that names none has kNoMeshTexcoord at all three corners.
  std::vector<std::array<float, 2>> texcoords;
  std::vector<std::uint32_t> corner_texcoords;
  // `usemtl`: the names in the order of their first use (where first used), and per triangle
  // the index of the name in force (kNoMeshMaterial before the file's first `usemtl`); both
  // empty when it names none.
  std::vector<MeshName> material_names;
  std::vector<std::uint32_t> triangle_names;
  std::vector<MeshName> libraries;  // `mtllib`, in file order
  // Per name: its material from the file's `mtllib` libraries, as an index into Scene::materials
  // (set by the scene's loader), or -1 for a name no library defines.
  std::vector<int> name_materials;
};

constexpr std::uint32_t kNoMeshMaterial = UINT32_MAX;
constexpr std::uint32_t kNoMeshTexcoord = UINT32_MAX;

// Triangle t's own material (index into Scene::materials) from its `usemtl` name, or -1.
int mesh_face_material(const MeshData& mesh, std::size_t t);

// The material of triangle t of `mesh` placed by `instance`: its own (mesh_face_material) where it
// has one and the instance keeps them (InstanceSpec::mesh_materials), else the instance's.
int mesh_triangle_material(const InstanceSpec& instance, const MeshData& mesh, std::size_t t);

// A `triangle` command: vertices already transformed to world space by the current M.
struct TriangleSpec {
  Vec3 v0, v1, v2;
  int material = 0;
  // (u, v) at each corner; the default (0, 0), (1, 0), (0, 1) unless the command gives them.
  std::array<float, 6> uv{0, 0, 1, 0, 0, 1};
  bool has_uv = false;
};

struct Scene {
  std::string path;
  CameraSpec camera;
  Vec3 background{0, 0, 0};
  int width = 500, height = 300;
  int max_depth = 5;
  int samples = 1;
  std::vector<MaterialSpec> materials;  // [0] is the default material
  std::vector<LightSpec> lights;
  std::optional<EnvironmentSpec> environment;  // none: escaping rays see `background`
  std::vector<TextureSpec> textures;
  std::vector<TextureImage> texture_images;
  // A deque grows without copying what it holds: a vector's doubling held up to three times
  // the table at its last growth, the peak of loading a scene of spheres.
  std::deque<InstanceSpec> instances;
  std::vector<Mat4> end_transforms;  // moving objects' poses at time 1 (`endpose`)
  std::vector<MeshData> meshes;
  std::vector<TriangleSpec> triangles;
  // What the loader read but cannot render as written ("FILE:LINE:COLUMN: warning: ..."), each
  // said once: shown before the render.
  std::vector<std::string> warnings;
};

// Where `instance` was written in `scene`'s file, for messages.
SourceLocation instance_location(const Scene& scene, const InstanceSpec& instance);

// Reads a scene file: NFF when its name ends in `.nff` (any case), else `.ray` (and the meshes it
// names). Throws SceneError on any problem in the file.
// The files come from `files`: the disk unless they were received (an MPI rank).
Scene load_scene(const std::string& path, const FileSource& files = disk_files());

}  // namespace clrt

// Writes the commands of a .ray scene (ray-format.md) that the generated scenes use.
#pragma once

#include <string>

#include "math/vec3.hpp"
#include "text_file.hpp"

namespace clrt::scenes {

struct Shot {
  Vec3 eye, lookat;
  double fov_degrees = 60;
  int width = 512, height = 512;
};

// `material r g b ka kd ks n kr kt [ior]` (the ior is written only when it is not 1).
struct Look {
  Vec3 colour;
  double ka = 0.1, kd = 0.8, ks = 0.3, shininess = 30, kr = 0, kt = 0, ior = 1;
};

// Where an instance of a model goes: scaled uniformly, tilted about x, turned about y, moved.
struct Placement {
  double scale = 1, tilt_degrees = 0, yaw_degrees = 0;
  Vec3 position;
  int look = 0;  // index into the scene's palette
};

class RayWriter {
 public:
  // `description` becomes the file's first comment line.
  RayWriter(const std::string& path, const std::string& description);

  void camera(const Shot& shot, const Vec3& background);
  void point_light(const Vec3& colour, const Vec3& position);
  void area_light(const Vec3& colour, const Vec3& corner, const Vec3& u, const Vec3& v, int samples);
  void depth_and_samples(int max_depth, int samples);
  void material(const Look& look);
  void floor_plane();
  void sphere(const Vec3& centre, double radius);
  // `mesh` is the model's file name, relative to the scene's folder.
  void mesh_instance(const std::string& mesh, const Placement& placement);
  // Any other command lines, as written (no line end needed).
  void line(const std::string& text) { out_.print("%s\n", text.c_str()); }
  void close() { out_.close(); }

 private:
  TextFile out_;
};

}  // namespace clrt::scenes

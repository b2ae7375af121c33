#include "obj_writer.hpp"

#include "text_file.hpp"

namespace clrt::scenes {

void write_obj(const std::string& path, const TriangleMesh& mesh) {
  TextFile out(path);
  out.print("# clrt-make-scenes: %zu vertices, %zu triangles\n", mesh.positions.size(),
            mesh.corners.size() / 3);
  for (const Vec3& p : mesh.positions) out.print("v %.7g %.7g %.7g\n", p.x, p.y, p.z);
  for (const Vec3& n : mesh.normals) out.print("vn %.6g %.6g %.6g\n", n.x, n.y, n.z);
  for (std::size_t k = 0; k < mesh.corners.size(); k += 3) {
    // OBJ indices start at 1; each corner's normal has its position's index.
    const unsigned a = mesh.corners[k] + 1, b = mesh.corners[k + 1] + 1,
                   c = mesh.corners[k + 2] + 1;
    out.print("f %u//%u %u//%u %u//%u\n", a, a, b, b, c, c);
  }
  out.close();
}

}  // namespace clrt::scenes

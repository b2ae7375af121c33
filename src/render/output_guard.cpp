#include "render/output_guard.hpp"

#include <filesystem>
#include <vector>

#include "image/image.hpp"

namespace clrt {

void check_output_is_not_input(const std::string& output, const Scene& scene) {
  std::vector<std::pair<std::string, std::string>> inputs = {{"the scene", scene.path}};
  for (const MeshData& mesh : scene.meshes) inputs.emplace_back("the mesh", mesh.path);
  for (const auto& [what, path] : inputs) {
    std::error_code ec;
    // equivalent() is false (with an error) when either file is missing: a new output is safe.
    if (std::filesystem::equivalent(output, path, ec))
      throw ImageError("the output " + output + " is " + what + " " + path +
                       " itself; name another output with -o");
  }
}

}  // namespace clrt

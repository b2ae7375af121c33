// The large procedural scenes of tools/make_scenes/README.md, written into one folder.
#pragma once

#include <string>
#include <vector>

namespace clrt::scenes {

// Every count (spheres, triangles, instances) is multiplied by `scale` (at least 1 of each,
// at least 18 triangles per mesh); the file names keep the full-size counts. Returns the
// paths written, scenes and meshes alike. Throws std::runtime_error when a file cannot be
// written.
std::vector<std::string> write_large_scenes(const std::string& folder, double scale);

// The count that `scale` makes of a full-size count.
long long scaled_count(long long full_size, double scale);

}  // namespace clrt::scenes

// The NFF files kept in the repository with their .ray twins: SPD scenes with the conversion in
// ../shared/scenes/spd-ray/ (see tests/scene/data/nff/README.md), and two scenes written for
// what SPD does not use, converted by hand.
#pragma once

#include <string>
#include <vector>

namespace clrt::test {

struct NffTwin {
  std::string nff, ray;  // absolute paths
};

inline std::vector<NffTwin> nff_twins() {
  const std::string spd = std::string(CLRT_SOURCE_DIR) + "/scenes/spd/";
  const std::string data = std::string(CLRT_SOURCE_DIR) + "/tests/scene/data/nff/";
  std::vector<NffTwin> twins;
  for (const char* name : {"balls-1", "tetra-2"})
    twins.push_back({spd + name + ".nff", spd + name + ".ray"});
  for (const char* name : {"tree-1", "jacks-1", "teapot-1", "mount-1", "lights", "shapes"})
    twins.push_back({data + name + ".nff", data + name + ".ray"});
  return twins;
}

}  // namespace clrt::test

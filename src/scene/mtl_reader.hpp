// Wavefront MTL material libraries, read as written: what each `newmtl` block says.
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <unordered_map>
#include <vector>

#include "math/vec3.hpp"
#include "scene/source_location.hpp"

namespace clrt {

// A texture map statement (`map_Kd [options] FILE`).
struct MtlTextureRef {
  std::string path;      // as written: relative to the library's folder
  SourceLocation where;  // of the path
  bool clamp = false;    // -clamp on|off
  Vec3 scale{1, 1, 1};   // -s u [v [w]]
  Vec3 offset{0, 0, 0};  // -o u [v [w]]
  double bump_multiplier = 1;  // -bm (bump maps only)
};

// One `newmtl` block; absent statements stay empty.
struct MtlMaterial {
  std::string name;
  SourceLocation where;  // of the name
  std::optional<Vec3> kd, ks, ke;
  std::optional<double> ns, ni, dissolve;  // Ns, Ni, d (`Tr t` is d = 1 - t)
  std::optional<int> illum;                // 0..10
  std::optional<MtlTextureRef> map_kd, map_ks, map_bump;  // map_bump and bump are one
};

struct MtlLibrary {
  std::vector<MtlMaterial> materials;  // in file order; a repeated name: the later one counts
  // "FILE:LINE:COLUMN: warning: ..." for what clrt does not render, once per keyword or map
  // option, and for each repeated material name.
  std::vector<std::string> warnings;
  // Each name's last definition: its index in `materials`. An OBJ file may name a material per
  // face, so looking each name up among all of them would load such a file in quadratic time.
  std::unordered_map<std::string, std::size_t> last_definition;

  // The last material called `name`, or null.
  const MtlMaterial* find(std::string_view name) const;
};

// Reads the text of library `file` (the name used in messages). Throws SceneError at the word of a
// malformed statement: one before the first `newmtl`, a missing, extra, malformed or out-of-range
// number, a map without a file, an unknown map option or one short of its values, and a line
// continued with a final '\' (clrt does not join lines).
MtlLibrary parse_mtl(std::string_view text, const std::string& file);

}  // namespace clrt

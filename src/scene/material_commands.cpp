// material / surface: appends a material and makes it the current one; emission: one that glows;
// mtl: whether meshes keep their MTL materials.
#include "scene/command_table.hpp"
#include "scene/limits.hpp"
#include "text/nearest_name.hpp"

namespace clrt {
namespace {

// 9 numbers: r g b ka kd ks n kr kt; 10: ... ior; 11: r g b a ka kd ks n kr kt ior (a ignored).
void material(LoaderState& s, const CommandArgs& a) {
  a.require_count({9, 10, 11});
  const std::size_t k = a.count() == 11 ? 4 : 3;  // index of ka
  // The ignored alpha must be a number too, and errors are reported left to right.
  for (std::size_t i = 0; i < a.count(); ++i) a.number(i);
  MaterialSpec m;
  m.color = a.vec3(0);
  m.ka = a.number(k);
  m.kd = a.number(k + 1);
  m.ks = a.number(k + 2);
  m.shininess = a.number(k + 3);
  if (m.shininess < 0)
    throw a.error_at(k + 3, "the Phong exponent must be >= 0, found " + excerpt(a.word(k + 3).text));
  m.kr = a.number_in(k + 4, 0, 1, "kr");
  m.kt = a.number_in(k + 5, 0, 1, "kt");
  if (a.count() > 9) {
    const double ior = a.number(k + 6);
    m.ior = ior <= 0 ? 1 : ior;
  }
  s.scene.materials.push_back(m);
  s.material = static_cast<int>(s.scene.materials.size()) - 1;
}

// emission R G B: the objects that follow glow with radiance (R, G, B), in the current material
// otherwise. A copy of that material takes the emission, so the objects already made with it
// stay as they were.
void emission(LoaderState& s, const CommandArgs& a) {
  a.require_count({3});
  MaterialSpec m = s.scene.materials.at(static_cast<std::size_t>(s.material));
  m.emission = {a.number_in(0, 0, limits::kMaxNumber, "R"), a.number_in(1, 0, limits::kMaxNumber, "G"),
                a.number_in(2, 0, limits::kMaxNumber, "B")};
  s.scene.materials.push_back(m);
  s.material = static_cast<int>(s.scene.materials.size()) - 1;
}

// mtl on|off: whether the meshes placed after it give their `usemtl` faces the materials of
// their MTL libraries (on, the default) or the current material to every face (off).
void mtl(LoaderState& s, const CommandArgs& a) {
  a.require_count({1});
  const std::string word = lower_case(a.word(0).text);
  if (word != "on" && word != "off") {
    const std::string near = did_you_mean(word, {"off", "on"});  // "of" is one edit from either
    throw a.error_at(0, "mtl takes on or off, found '" + excerpt(a.word(0).text) + "'" +
                            in_parentheses(near));
  }
  s.mesh_materials = word == "on";
}

}  // namespace

void add_material_commands(CommandTable& table) {
  table["material"] = material;
  table["surface"] = material;
  table["emission"] = emission;
  table["mtl"] = mtl;
}

}  // namespace clrt

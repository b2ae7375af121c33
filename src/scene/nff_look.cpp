// b, l, f: the background, the lights and the material of the objects after it.
#include <cmath>

#include "scene/nff_state.hpp"

namespace clrt {
namespace {

void background(NffState& s, const CommandArgs& a) {
  a.require_count({3});
  s.loader.scene.background = a.vec3(0);
}

// l x y z [r g b]: a point light.
void light(NffState& s, const CommandArgs& a) {
  a.require_count({3, 6});
  LightSpec spec;
  spec.kind = "point";
  spec.position = a.vec3(0);
  if (a.count() == 6)
    spec.color = a.vec3(3);
  else
    s.uncoloured_lights.push_back(s.loader.scene.lights.size());
  s.loader.scene.lights.push_back(spec);
}

// NFF (and the MTV ray tracer it was written for) adds its terms:
//   I = Kd diffuse + Ks highlight + Ks reflected + T transmitted   (Ks is also the reflectivity)
// while clrt weights the local terms by w = 1 - kr - kt. With kr = Ks and kt = T, dividing the
// local coefficients by w gives NFF's sum. ka = 0.1 is the ambient SPD's own readers assume.
MaterialSpec material_from_nff(const Vec3& color, double kd, double ks, double shine, double t,
                               double ior) {
  MaterialSpec m;
  m.color = color;
  m.kr = ks;
  m.kt = t;
  m.shininess = shine;
  m.ior = ior <= 0 ? 1 : ior;
  // When Ks + T >= 1 no local weight is left to divide by: the local term is lost.
  const double w = 1 - ks - t;
  const double divisor = w > 0 ? w : 1;
  m.ka = 0.1 / divisor;
  m.kd = kd / divisor;
  m.ks = ks / divisor;
  return m;
}

// f r g b Kd Ks Shine T index_of_refraction
void fill(NffState& s, const CommandArgs& a) {
  a.require_count({8});
  for (std::size_t i = 0; i < a.count(); ++i) a.number(i);  // errors left to right
  const double ks = a.number_in(4, 0, 1, "Ks (also the reflectivity)");
  const double shine = a.number(5);
  if (shine < 0)
    throw a.error_at(5, "the Phong exponent (Shine) must be >= 0, found " + a.word(5).text);
  const double t = a.number_in(6, 0, 1, "T (the transmittance)");
  Scene& scene = s.loader.scene;
  scene.materials.push_back(material_from_nff(a.vec3(0), a.number(3), ks, shine, t, a.number(7)));
  s.loader.material = static_cast<int>(scene.materials.size()) - 1;
}

}  // namespace

void add_nff_look_entities(NffTable& table) {
  table["b"] = background;
  table["l"] = light;
  table["f"] = fill;
}

// NFF leaves the intensity of a light without a colour to the reader. 1/sqrt(number of lights)
// is what SPD's generators write for renderers that need one (POV-Ray); no ambient light is added.
void finish_lights(NffState& s) {
  std::vector<LightSpec>& lights = s.loader.scene.lights;
  const double k = 1.0 / std::sqrt(static_cast<double>(lights.size()));
  for (std::size_t i : s.uncoloured_lights) lights[i].color = {k, k, k};
}

}  // namespace clrt

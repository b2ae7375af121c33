// The material-cost knob (README.md, "The material knob"): one layer of spheres over a floor,
// rendered with 1 to 16 distinct materials, each a different subset of path mode's four lobes,
// so that only the material mix changes from scene to scene.
#pragma once

#include <string>
#include <vector>

#include "ray_writer.hpp"

namespace clrt::scenes {

// The lobes of docs/path-tracing.md, one bit each.
enum Lobe : unsigned { kLambert = 1, kPhong = 2, kMirror = 4, kDielectric = 8 };

// The 16 subsets of the four lobes (the empty one a black absorber), cheapest to shade first.
const std::vector<unsigned>& knob_lobe_order();

// The material of a lobe subset: each lobe present carries 0.9 / (lobes present) of the light.
Look knob_look(unsigned lobes);

// "none", or the letters of the lobes present: d (Lambert), g (Phong), m (mirror), t (dielectric).
std::string lobe_letters(unsigned lobes);

// Writes knob-01.ray ... knob-16.ray (scene k: the k cheapest subsets, spread at random over the
// spheres in equal shares) and knob-lobes-LETTERS.ray (every sphere one subset, to measure its
// cost). `scale` multiplies the sphere count (at least 16). Returns the paths written; throws
// std::runtime_error when a file cannot be written.
std::vector<std::string> write_knob_scenes(const std::string& folder, double scale);

// The texture knob: the same spheres, every one with the Lambertian and Phong lobes, their
// materials told apart by textures of rising cost (docs/experiments.md).
struct TextureKnobEntry {
  std::string name;      // plain, checker, ..., as in texture-knob-only-NAME.ray
  std::string commands;  // the `texture` lines after the material, or none
};
const std::vector<TextureKnobEntry>& texture_knob_order();

// Writes the images the textures show (knob-64.png, knob-1024.png, knob-1024.pfm,
// knob-2048.png), texture-knob-1.ray ... texture-knob-8.ray (scene k: the first k entries of
// texture_knob_order(), in equal shares) and texture-knob-only-NAME.ray (every sphere one entry).
// Returns the paths written; throws when a file cannot be written.
std::vector<std::string> write_texture_knob_scenes(const std::string& folder, double scale);

// The number of spheres a scale gives: the side of a square grid, squared.
int knob_grid_side(double scale);

}  // namespace clrt::scenes

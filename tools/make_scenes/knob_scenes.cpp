#include "knob_scenes.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <functional>

#include "image/image.hpp"

#include "random_stream.hpp"

namespace clrt::scenes {
namespace {

constexpr int kFullSide = 24;
constexpr double kRadius = 0.42;  // on a grid of unit spacing: neighbours almost touch
const Look kFloor{{0.6, 0.6, 0.6}, 0, 0.8, 0, 1, 0, 0};
const Vec3 kSky{0.25, 0.3, 0.35};

// A distinct colour for each subset (it tints only the Lambertian lobe), so the mix shows.
Vec3 hue(unsigned lobes) {
  const double a = 0.3 + 0.7 * ((lobes * 5) % 16) / 15.0;
  const double b = 0.3 + 0.7 * ((lobes * 11) % 16) / 15.0;
  return {1.0, a, b};
}

struct Sphere {
  Vec3 centre;
  int rank;  // its place in a seeded shuffle: scene k gives it material rank mod k
};

std::vector<Sphere> sphere_grid(int side) {
  std::vector<Sphere> spheres;
  for (int i = 0; i < side * side; ++i)
    spheres.push_back({{i % side - (side - 1) / 2.0, kRadius, i / side - (side - 1) / 2.0}, i});
  // Fisher-Yates on the ranks; the modulo's bias is far below one sphere at these counts.
  RandomStream random(17);
  for (std::size_t i = spheres.size() - 1; i > 0; --i)
    std::swap(spheres[i].rank, spheres[random.next_bits() % (i + 1)].rank);
  return spheres;
}

// Writes one knob scene: the spheres' materials are `looks` (each writes its material's
// commands), sphere s taking look rank(s) mod k.
void write_scene(const std::string& path, const std::string& description,
                 const std::vector<Sphere>& spheres, int side,
                 const std::vector<std::function<void(RayWriter&)>>& looks) {
  RayWriter out(path, description);
  out.camera({{0, 0.8 * side, 0.75 * side}, {0, 0, 0.05 * side}, 50, 160, 120}, kSky);
  out.depth_and_samples(6, 4);
  out.area_light({4, 4, 4}, {-0.25 * side, 1.2 * side, -0.25 * side}, {0.5 * side, 0, 0},
                 {0, 0, 0.5 * side}, 4);
  out.material(kFloor);
  out.floor_plane();
  const int k = static_cast<int>(looks.size());
  for (int m = 0; m < k; ++m) {
    looks[static_cast<std::size_t>(m)](out);
    for (const Sphere& s : spheres)
      if (s.rank % k == m) out.sphere(s.centre, kRadius);
  }
  out.close();
}

std::vector<std::function<void(RayWriter&)>> lobe_looks(const std::vector<unsigned>& mix) {
  std::vector<std::function<void(RayWriter&)>> looks;
  for (unsigned lobes : mix) looks.push_back([lobes](RayWriter& out) { out.material(knob_look(lobes)); });
  return looks;
}

// A texel of a generated image: value noise of a few octaves from a seeded hash, coloured per
// image, so that neighbouring pixels read unrelated memory no more than a real picture would.
Vec3 texel(int x, int y, int size, unsigned seed) {
  double v = 0, amplitude = 0.5;
  for (int cell = size / 4; cell >= 1; cell /= 4, amplitude *= 0.5) {
    const unsigned h = (static_cast<unsigned>(x / cell) * 73856093u) ^ (static_cast<unsigned>(y / cell) * 19349663u) ^
                       (seed * 83492791u);
    v += amplitude * ((h * 2654435761u) >> 24) / 255.0;
  }
  return {0.2 + 0.8 * v, 0.2 + 0.6 * v * v, 0.1 + 0.9 * (1 - v) * v};
}

void write_texture_image(const std::string& path, int size, unsigned seed, bool linear) {
  if (linear) {
    std::vector<float> rgb;
    for (int y = 0; y < size; ++y)
      for (int x = 0; x < size; ++x) {
        const Vec3 c = texel(x, y, size, seed);
        rgb.insert(rgb.end(), {static_cast<float>(c.x), static_cast<float>(c.y), static_cast<float>(c.z)});
      }
    write_image(path, FloatImage(size, size, std::move(rgb)));
    return;
  }
  std::vector<std::uint8_t> rgba;
  for (int y = 0; y < size; ++y)
    for (int x = 0; x < size; ++x) {
      const Vec3 c = texel(x, y, size, seed);
      for (double channel : {c.x, c.y, c.z}) rgba.push_back(static_cast<std::uint8_t>(std::lround(255 * channel)));
      rgba.push_back(255);
    }
  write_image(path, Rgba8Image(size, size, {std::move(rgba)}));
}

}  // namespace

// Measured: the wavefront's shade time per shaded ray of each knob-lobes scene on PoCL
// (README.md, "The material knob"). The four subsets without a Lambertian or Phong lobe take
// no shadow rays and cost about half as much as the rest.
const std::vector<unsigned>& knob_lobe_order() {
  static const std::vector<unsigned> order = {
      kDielectric,
      0,
      kMirror | kDielectric,
      kMirror,
      kLambert | kMirror | kDielectric,
      kLambert | kMirror,
      kLambert | kDielectric,
      kPhong,
      kPhong | kMirror | kDielectric,
      kPhong | kDielectric,
      kLambert | kPhong | kMirror | kDielectric,
      kPhong | kMirror,
      kLambert | kPhong | kDielectric,
      kLambert | kPhong,
      kLambert,
      kLambert | kPhong | kMirror};
  return order;
}

Look knob_look(unsigned lobes) {
  int present = 0;
  for (unsigned bit = 1; bit <= kDielectric; bit <<= 1) present += (lobes & bit) != 0;
  const double w = present > 0 ? 0.9 / present : 0;
  const double kr = lobes & kMirror ? w : 0, kt = lobes & kDielectric ? w : 0;
  // path_lobes scales kd and ks by (1 - kr - kt), so they are divided by it here.
  const double share = 1 - kr - kt;
  return {hue(lobes), 0, lobes & kLambert ? w / share : 0, lobes & kPhong ? w / share : 0,
          40, kr, kt, lobes & kDielectric ? 1.5 : 1};
}

std::string lobe_letters(unsigned lobes) {
  std::string letters;
  if (lobes & kLambert) letters += 'd';
  if (lobes & kPhong) letters += 'g';
  if (lobes & kMirror) letters += 'm';
  if (lobes & kDielectric) letters += 't';
  return letters.empty() ? "none" : letters;
}

int knob_grid_side(double scale) {
  const double spheres = std::max(16.0, kFullSide * kFullSide * scale);
  return static_cast<int>(std::ceil(std::sqrt(spheres) - 1e-9));
}

std::vector<std::string> write_knob_scenes(const std::string& folder, double scale) {
  std::filesystem::create_directories(folder);
  const int side = knob_grid_side(scale);
  const std::vector<Sphere> spheres = sphere_grid(side);
  const std::vector<unsigned>& order = knob_lobe_order();
  const std::string grid = std::to_string(side * side) + " spheres over a floor";
  std::vector<std::string> files;
  for (std::size_t k = 1; k <= order.size(); ++k) {
    char name[32];
    std::snprintf(name, sizeof name, "knob-%02zu.ray", k);
    files.push_back((std::filesystem::path(folder) / name).string());
    write_scene(files.back(), "the material knob: " + std::to_string(k) + " materials on " + grid,
                spheres, side, lobe_looks({order.begin(), order.begin() + static_cast<long>(k)}));
  }
  for (const unsigned lobes : order) {
    files.push_back(
        (std::filesystem::path(folder) / ("knob-lobes-" + lobe_letters(lobes) + ".ray")).string());
    write_scene(files.back(), "the material knob: lobes " + lobe_letters(lobes) + " on " + grid,
                spheres, side, lobe_looks({lobes}));
  }
  return files;
}

const std::vector<TextureKnobEntry>& texture_knob_order() {
  static const std::vector<TextureKnobEntry> order = {
      {"plain", ""},
      {"checker", "texture color checker 1 1 1 0.2 0.2 0.2 scale 8 8"},
      {"noise4", "texture color noise 0.9 0.5 0.2 0.2 0.3 0.8 scale 8 8 octaves 4"},
      {"png64", "texture color image knob-64.png"},
      {"png1024", "texture color image knob-1024.png"},
      {"pfm1024", "texture color image knob-1024.pfm"},
      {"noise8", "texture color noise 0.2 0.8 0.3 0.9 0.9 0.6 scale 8 8 octaves 8"},
      {"png2048-ks", "texture color image knob-2048.png\ntexture ks noise 0 0 0 1 1 1 scale 16 16"},
  };
  return order;
}

std::vector<std::string> write_texture_knob_scenes(const std::string& folder, double scale) {
  std::filesystem::create_directories(folder);
  const auto in_folder = [&](const std::string& name) { return (std::filesystem::path(folder) / name).string(); };
  std::vector<std::string> files;
  const struct {
    const char* name;
    int size;
    bool linear;
  } images[] = {{"knob-64.png", 64, false}, {"knob-1024.png", 1024, false}, {"knob-1024.pfm", 1024, true},
                {"knob-2048.png", 2048, false}};
  unsigned seed = 1;
  for (const auto& image : images) {
    files.push_back(in_folder(image.name));
    write_texture_image(files.back(), image.size, seed++, image.linear);
  }
  const int side = knob_grid_side(scale);
  const std::vector<Sphere> spheres = sphere_grid(side);
  const std::string grid = std::to_string(side * side) + " spheres over a floor";
  // Every material has the Lambertian and Phong lobes; only its textures differ.
  const auto look = [](const TextureKnobEntry& e) {
    return [e](RayWriter& out) {
      out.material(knob_look(kLambert | kPhong));
      if (!e.commands.empty()) out.line(e.commands);
    };
  };
  const std::vector<TextureKnobEntry>& order = texture_knob_order();
  std::vector<std::function<void(RayWriter&)>> looks;
  for (std::size_t k = 1; k <= order.size(); ++k) {
    looks.push_back(look(order[k - 1]));
    files.push_back(in_folder("texture-knob-" + std::to_string(k) + ".ray"));
    write_scene(files.back(), "the texture knob: " + std::to_string(k) + " materials on " + grid, spheres, side, looks);
  }
  for (const TextureKnobEntry& e : order) {
    files.push_back(in_folder("texture-knob-only-" + e.name + ".ray"));
    write_scene(files.back(), "the texture knob: every sphere " + e.name + " on " + grid, spheres, side, {look(e)});
  }
  return files;
}

}  // namespace clrt::scenes

#include "render/frame_setup.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>

#include "math/cumulative_shares.hpp"
#include "scene/device_vector.hpp"
#include "scene/light_kinds.hpp"
#include "scene/limits.hpp"

namespace clrt {

RenderOptions RenderOptions::from_scene(const Scene& scene) {
  RenderOptions o;
  o.width = scene.width;
  o.height = scene.height;
  o.samples = scene.samples;
  o.max_depth = scene.max_depth;
  return o;
}

// dir(x, y) = f F + (x - w/2) R + (h/2 - y) U for continuous pixel coordinates (x, y), with
// the focal length f = w / (2 tan(fov / 2)) in pixels (fov across the width).
dev::Camera make_camera(const Scene& scene, const RenderOptions& options) {
  return make_camera(scene.camera, options);
}

dev::Camera make_camera(const CameraSpec& c, const RenderOptions& options) {
  const Vec3 forward = normalize(c.lookat - c.eye);
  const Vec3 right = normalize(cross(forward, c.up));
  const Vec3 up = cross(right, forward);
  const double w = options.width, h = options.height;
  const double focal = w / (2.0 * std::tan(c.fov_degrees * M_PI / 360.0));
  dev::Camera cam{};
  cam.eye = f4_of(c.eye);
  cam.corner = f4_of(forward * focal - right * (w / 2) + up * (h / 2));
  cam.pixel_dx = f4_of(right);
  cam.pixel_dy = f4_of(-up);
  if (c.lens_radius > 0) {
    cam.thin_lens = 1;
    cam.lens_u = f4_of(right * c.lens_radius);
    cam.lens_v = f4_of(-up * c.lens_radius);
    // A pixel's direction has length `focal` along the view, so this takes it to the plane in
    // focus.
    cam.lens_u.w = static_cast<float>(c.focus_distance / focal);
  }
  cam.shutter_open = static_cast<float>(c.shutter_open);
  cam.shutter_close = static_cast<float>(c.shutter_close);
  cam.width = static_cast<dev::u32>(options.width);
  cam.height = static_cast<dev::u32>(options.height);
  cam.samples = static_cast<dev::u32>(options.samples);
  const Grid grid = stratification_grid(cam.samples);
  cam.grid_u = grid.u;
  cam.grid_v = grid.v;
  cam.seed = options.seed;
  // Path mode's estimates converge faster on stratified Sobol samples; the Whitted modes keep
  // the jittered grid their images were made with.
  cam.sampler = options.mode == RenderMode::Path ? CLRT_SAMPLER_SOBOL : CLRT_SAMPLER_STRATIFIED;
  return cam;
}

std::vector<dev::Material> make_materials(const Scene& scene) {
  std::vector<dev::Material> out;
  for (const MaterialSpec& m : scene.materials) {
    dev::Material d{};
    d.color = f4_of(m.color);
    d.emission = f4_of(m.emission);
    d.emission.w = m.emission.x != 0 || m.emission.y != 0 || m.emission.z != 0 ? 1.0f : 0.0f;
    d.ka = static_cast<float>(m.ka);
    d.kd = static_cast<float>(m.kd);
    d.ks = static_cast<float>(m.ks);
    d.shininess = static_cast<float>(m.shininess);
    d.kr = static_cast<float>(m.kr);
    d.kt = static_cast<float>(m.kt);
    d.ior = static_cast<float>(m.ior);
    for (std::size_t slot = 0; slot < CLRT_TEXTURE_SLOTS; ++slot)
      d.textures[slot] = m.textures[slot] < 0 ? CLRT_NO_TEXTURE : texture_row(m.textures[slot]);
    out.push_back(d);
  }
  return out;
}

std::vector<dev::Light> make_lights(const Scene& scene) {
  std::vector<dev::Light> out;
  dev::u32 first_sample = 0;
  for (const LightSpec& l : scene.lights) {
    const LightKindEntry& entry = light_kind(l.kind);
    if (!entry.to_device) continue;  // ambient light: summed into RenderParams.ambient
    dev::Light d{};
    d.color = f4_of(l.color);
    d.position = f4_of(l.position);
    d.samples = static_cast<dev::u32>(shadow_samples(l));
    d.grid_u = d.grid_v = 1;
    entry.to_device(l, d);
    d.first_sample = first_sample;
    first_sample += d.samples;
    out.push_back(d);
  }
  return out;
}

dev::u32 device_mode(RenderMode mode) {
  switch (mode) {
    case RenderMode::Trace: return CLRT_MODE_TRACE;
    case RenderMode::Cast: return CLRT_MODE_CAST;
    case RenderMode::Path: return CLRT_MODE_PATH;
  }
  return CLRT_MODE_TRACE;
}

dev::RenderParams make_params(const Scene& scene, const RenderOptions& options) {
  dev::RenderParams p{};
  p.background = f4_of(scene.background);
  Vec3 ambient;
  for (const LightSpec& l : scene.lights) {
    if (!light_kind(l.kind).to_device) {
      ambient = ambient + l.color;
    } else {
      ++p.light_count;  // an entry of make_lights' table
      p.shadow_samples += static_cast<dev::u32>(shadow_samples(l));
    }
  }
  p.ambient = f4_of(ambient);
  p.max_depth = static_cast<dev::u32>(options.max_depth);
  p.mode = device_mode(options.mode);
  p.epsilon = kEpsilon;
  p.max_sample_value = options.max_sample_value;
  p.glow_light = p.environment = CLRT_NO_LIGHT;  // make_frame adds them
  p.glossy = options.glossy && options.mode == RenderMode::Trace ? 1u : 0u;
  // A pixel at the image's centre spans 1 / focal radians, the focal length in pixels as
  // make_camera has it.
  p.cone_spread = static_cast<float>(2.0 * std::tan(scene.camera.fov_degrees * M_PI / 360.0) / options.width);
  return p;
}

namespace {

// Texels (rgb radiance times the scale; w the row's cumulative share through the texel) and then
// the rows' cumulative shares, four to an f4. A texel's weight is its luminance times the sine
// at its row's centre (its solid angle); a row without light shares its weight evenly. Sets the
// record's size and tells whether anything can be sampled.
std::vector<dev::f4> environment_table(const EnvironmentSpec& env, dev::Light& record, bool& sampled) {
  const auto w = static_cast<std::size_t>(env.width), h = static_cast<std::size_t>(env.height);
  std::vector<dev::f4> table(w * h + (h + 3) / 4);
  std::vector<double> row_weight(h);
  for (std::size_t j = 0; j < h; ++j) {
    const double sine = std::sin(M_PI * (static_cast<double>(j) + 0.5) / static_cast<double>(h));
    std::vector<double> lum(w);
    double sum = 0;
    for (std::size_t i = 0; i < w; ++i) {
      const float* rgb = &env.rgb[3 * (j * w + i)];
      dev::f4& t = table[j * w + i];
      t.x = static_cast<float>(rgb[0] * env.scale);
      t.y = static_cast<float>(rgb[1] * env.scale);
      t.z = static_cast<float>(rgb[2] * env.scale);
      lum[i] = 0.2126 * t.x + 0.7152 * t.y + 0.0722 * t.z;
      sum += lum[i];
    }
    const std::vector<float> shares = cumulative_shares(lum);
    for (std::size_t i = 0; i < w; ++i) table[j * w + i].w = shares[i];
    row_weight[j] = sum * sine;
  }
  double total = 0;
  for (double r : row_weight) total += r;
  sampled = total > 0;
  const std::vector<float> row_shares = cumulative_shares(row_weight);
  std::copy(row_shares.begin(), row_shares.end(), &table[w * h].x);
  record.kind = dev::CLRT_LIGHT_ENVIRONMENT;
  record.grid_u = static_cast<dev::u32>(w);
  record.grid_v = static_cast<dev::u32>(h);
  record.samples = 1;
  // World to map: the rows of the rotation's inverse, its transpose.
  record.position = f4_of(env.rotation.column(0));
  record.direction = f4_of(env.rotation.column(1));
  record.edge_u = f4_of(env.rotation.column(2));
  return table;
}

constexpr dev::u32 kF4sPerLight = sizeof(dev::Light) / sizeof(dev::f4);
constexpr dev::u32 kF4sPerEmitter = sizeof(dev::Emitter) / sizeof(dev::f4);

}  // namespace

FrameData make_frame(const Scene& scene, const GeometryData& geometry, const RenderOptions& options) {
  FrameData frame{make_camera(scene, options), make_params(scene, options), make_materials(scene),
                  make_lights(scene), nullptr, std::make_shared<const TextureTable>(make_texture_table(scene))};
  const bool path = options.mode == RenderMode::Path;
  // Appends a record, counted among the sampled lights when `sampled`.
  const auto add = [&frame](dev::Light record, bool sampled) {
    record.first_sample = frame.params.shadow_samples;
    if (sampled) {
      ++frame.params.light_count;
      frame.params.shadow_samples += record.samples;
    }
    frame.lights.push_back(record);
    return static_cast<dev::u32>(frame.lights.size() - 1);
  };
  if (path && !geometry.emitters.empty()) {
    dev::Light glow{};
    glow.kind = dev::CLRT_LIGHT_GLOW;
    glow.color.w = static_cast<float>(geometry.emitter_power);
    glow.samples = 1;
    glow.grid_u = static_cast<dev::u32>(geometry.emitters.size());
    glow.grid_v = 1;
    frame.params.glow_light = add(glow, true);
  }
  if (scene.environment) {
    dev::Light record{};
    bool sampled = false;
    frame.environment_table =
        std::make_shared<const std::vector<dev::f4>>(environment_table(*scene.environment, record, sampled));
    frame.params.environment = add(record, path && sampled);
  }
  // The tables follow the records: the emitter rows, then the environment's.
  const auto records = static_cast<dev::u32>(frame.lights.size());
  const dev::u32 rows = frame.params.glow_light == CLRT_NO_LIGHT ? 0 : static_cast<dev::u32>(geometry.emitters.size());
  if (frame.params.glow_light != CLRT_NO_LIGHT)
    frame.lights[frame.params.glow_light].data = (records - frame.params.glow_light) * kF4sPerLight;
  if (frame.params.environment != CLRT_NO_LIGHT)
    frame.lights[frame.params.environment].data =
        (records - frame.params.environment) * kF4sPerLight + rows * kF4sPerEmitter;
  return frame;
}

std::vector<unsigned char> light_table_bytes(const FrameData& frame, const GeometryData& geometry) {
  const std::size_t light_bytes = sizeof(dev::Light) * frame.lights.size();
  const std::size_t row_bytes =
      frame.params.glow_light == CLRT_NO_LIGHT ? 0 : sizeof(dev::Emitter) * geometry.emitters.size();
  const std::size_t environment_bytes =
      frame.environment_table ? sizeof(dev::f4) * frame.environment_table->size() : 0;
  std::vector<unsigned char> bytes(light_bytes + row_bytes + environment_bytes);
  if (light_bytes) std::memcpy(bytes.data(), frame.lights.data(), light_bytes);
  if (row_bytes) std::memcpy(bytes.data() + light_bytes, geometry.emitters.data(), row_bytes);
  if (environment_bytes)
    std::memcpy(bytes.data() + light_bytes + row_bytes, frame.environment_table->data(), environment_bytes);
  return bytes;
}

}  // namespace clrt

#include "whitted_tracer.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <vector>

#include "host_rays.hpp"
#include "host_threads.hpp"
#include "render/frame_setup.hpp"

namespace clrt::compare {
namespace {

Vec3 mul(const Vec3& a, const Vec3& b) { return {a.x * b.x, a.y * b.y, a.z * b.z}; }

Vec3 vec3_of(const dev::f4& v) { return {v.x, v.y, v.z}; }

// One light as seen from a point: the unit direction towards it, how far it is (infinite for a
// directional light) and the colour that arrives (zero outside a spot's cone).
struct Incoming {
  Vec3 to_light;
  double distance;
  Vec3 colour;
};

// The lights come as the renderer sets them up once per frame (render/frame_setup.hpp): the
// ambient ones summed, directions unit, a spot's cut-off as a cosine.
class Tracer {
 public:
  Tracer(const Scene& scene, const EmbreeScene& embree, const RenderOptions& options)
      : embree_(embree),
        materials_(scene.materials),
        lights_(make_lights(scene)),
        ambient_(vec3_of(make_params(scene, options).ambient)),
        background_(scene.background),
        max_depth_(options.max_depth) {}

  // What the ray o + t d (d unit) carrying `weight` brings back, `depth` bounces from the eye.
  Vec3 trace(const Vec3& o, const Vec3& d, const Vec3& weight, int depth) const {
    const SurfaceHit hit = embree_.closest_hit(host_ray(o, d, INFINITY));
    if (!std::isfinite(hit.t)) return mul(weight, background_);
    const MaterialSpec& m = materials_[static_cast<std::size_t>(hit.material)];
    const Vec3 p = o + d * hit.t;
    const bool front = dot(hit.normal, d) < 0;
    const Vec3 ng = front ? hit.normal : -hit.normal;
    const Vec3 n = dot(hit.shading_normal, ng) < 0 ? -hit.shading_normal : hit.shading_normal;
    const Vec3 base = weight * std::max(0.0, 1 - m.kr - m.kt);
    Vec3 colour = mul(mul(base, ambient_), m.color) * m.ka;
    for (const dev::Light& light : lights_) {
      const Incoming in = arriving(light, p);
      const Vec3 term = mul(base, local_term(m, n, -d, in));
      if (term == Vec3{}) continue;
      const Vec3 from = offset(p, ng, in.to_light);
      const Vec3 towards = vec3_of(light.position) - from;
      const HostRay shadow = std::isinf(in.distance)
                                 ? host_ray(from, in.to_light, INFINITY)
                                 : host_ray(from, normalize(towards), static_cast<float>(length(towards)));
      if (!embree_.occluded(shadow)) colour = colour + term;
    }
    if (depth >= max_depth_) return colour;
    // Snell's law with eta = n1 / n2; total internal reflection sends kt along the mirror ray.
    const double eta = front ? 1 / m.ior : m.ior, cos_i = -dot(d, n);
    const double k = 1 - eta * eta * (1 - cos_i * cos_i);
    const bool refracts = m.kt > 0 && k >= 0;
    const double mirror_share = m.kr + (m.kt > 0 && !refracts ? m.kt : 0);
    if (mirror_share > 0) {
      const Vec3 r = d - n * (2 * dot(d, n));
      colour = colour + trace(offset(p, ng, r), r, weight * mirror_share, depth + 1);
    }
    if (refracts) {
      const Vec3 t = normalize(d * eta + n * (eta * cos_i - std::sqrt(k)));
      colour = colour + trace(offset(p, ng, t), t, weight * m.kt, depth + 1);
    }
    return colour;
  }

 private:
  // p moved by epsilon along ng to the side `dir` leaves through.
  static Vec3 offset(const Vec3& p, const Vec3& ng, const Vec3& dir) {
    return p + ng * (dot(ng, dir) >= 0 ? kTmin : -kTmin);
  }

  // Only the kinds traced_kind() accepts reach here.
  static Incoming arriving(const dev::Light& light, const Vec3& p) {
    if (light.kind == dev::CLRT_LIGHT_DIRECTIONAL) return {-vec3_of(light.direction), INFINITY, vec3_of(light.color)};
    const Vec3 delta = vec3_of(light.position) - p;
    Incoming in{delta / length(delta), length(delta), vec3_of(light.color)};
    if (light.kind == dev::CLRT_LIGHT_SPOT) {
      const double sd = dot(vec3_of(light.direction), -in.to_light);
      in.colour = sd >= light.cos_cutoff ? in.colour * std::pow(std::max(sd, 0.0), light.spot_exponent) : Vec3{};
    }
    return in;
  }

  // kd Ld C (N.L) + ks Ld max(0, R.V)^n, zero where N.L <= 0.
  static Vec3 local_term(const MaterialSpec& m, const Vec3& n, const Vec3& v, const Incoming& in) {
    const double nl = dot(n, in.to_light);
    if (nl <= 0) return {};
    const Vec3 r = n * (2 * nl) - in.to_light;
    const double highlight = m.ks == 0 ? 0 : std::pow(std::max(0.0, dot(r, v)), m.shininess);
    return mul(in.colour, m.color) * (m.kd * nl) + in.colour * (m.ks * highlight);
  }

  const EmbreeScene& embree_;
  const std::vector<MaterialSpec>& materials_;
  std::vector<dev::Light> lights_;
  Vec3 ambient_, background_;
  int max_depth_;
};

}  // namespace

namespace {

// The kinds whose light arriving() computes; any other kind (an area light, or one added after
// this tracer) is refused, never shaded as one of these.
bool traced_kind(const std::string& kind) {
  return kind == "ambient" || kind == "point" || kind == "directional" || kind == "spot";
}

}  // namespace

std::string unsupported_lights(const Scene& scene) {
  std::map<std::string, int> refused;  // by kind name, in name order
  for (const LightSpec& l : scene.lights)
    if (!traced_kind(l.kind)) ++refused[l.kind];
  std::string out;
  for (const auto& [name, count] : refused)
    out += (out.empty() ? "" : ", ") + std::to_string(count) + " " + name +
           (count == 1 ? " light" : " lights");
  // The light that comes from no `light` command: glowing surfaces, and an environment image.
  for (const MaterialSpec& m : scene.materials)
    if (m.emission.x > 0 || m.emission.y > 0 || m.emission.z > 0) {
      out += std::string(out.empty() ? "" : ", ") + "glowing surfaces";
      break;
    }
  if (scene.environment) out += std::string(out.empty() ? "" : ", ") + "an environment image";
  return out;
}

FloatImage render_whitted(const Scene& scene, const EmbreeScene& embree, const RenderOptions& options,
                          int threads) {
  const CameraRays camera(scene, options);
  const Tracer tracer(scene, embree, options);
  const std::size_t width = camera.width(), pixels = width * camera.height();
  std::vector<float> rgb(3 * pixels);
  parallel_seconds(pixels, threads, [&](std::size_t begin, std::size_t end) {
    flush_denormals();
    for (std::size_t k = begin; k < end; ++k) {
      const HostRay ray = camera.through(static_cast<unsigned>(k % width), static_cast<unsigned>(k / width));
      const Vec3 c = tracer.trace(ray.origin_vec(), ray.dir_vec(), {1, 1, 1}, 0);
      rgb[3 * k] = static_cast<float>(c.x);
      rgb[3 * k + 1] = static_cast<float>(c.y);
      rgb[3 * k + 2] = static_cast<float>(c.z);
    }
  });
  return {static_cast<int>(camera.width()), static_cast<int>(camera.height()), std::move(rgb)};
}

}  // namespace clrt::compare

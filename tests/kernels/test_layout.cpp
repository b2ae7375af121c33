// The device must see every shared structure with the host's size and field offsets.
#include <catch2/catch.hpp>

#include <cstddef>
#include <string>
#include <vector>

#include "cl_fixture.hpp"
#include "shared/bvh.h"
#include "shared/ray.h"
#include "shared/scene.h"

using namespace clrt;

namespace {

// Each entry is the sizeof or offsetof expression, evaluated by both compilers.
#define LAYOUT_FIELDS(X)                                                                     \
  X(sizeof(Ray)) X(offsetof(Ray, radiance_scale)) X(offsetof(Ray, dir))                     \
  X(offsetof(Ray, sample_cone)) X(offsetof(Ray, weight)) X(offsetof(Ray, pdf))              \
  X(offsetof(Ray, sample))                                                                   \
  X(offsetof(Ray, depth_kind)) X(offsetof(Ray, time)) X(sizeof(Hit)) X(offsetof(Hit, shading_normal))                     \
  X(offsetof(Hit, instance)) X(offsetof(Hit, material)) X(sizeof(ShadowRay))                 \
  X(offsetof(ShadowRay, contribution)) X(offsetof(ShadowRay, owner))                        \
  X(offsetof(ShadowRay, time)) X(sizeof(Camera)) X(offsetof(Camera, shutter_close))         \
  X(offsetof(Instance, motion)) X(offsetof(Instance, material_rows)) X(sizeof(InstanceMotion)) X(offsetof(InstanceMotion, rotation)) \
  X(offsetof(InstanceMotion, stretch_off)) X(offsetof(InstanceMotion, inverse_sine))        \
  X(offsetof(BvhMeshInstancePacket, motion))                                                 \
  X(offsetof(Camera, pixel_dy)) X(offsetof(Camera, width)) X(offsetof(Camera, seed))         \
  X(offsetof(Camera, sampler)) X(offsetof(Camera, lens_u)) X(offsetof(Camera, lens_v))      \
  X(offsetof(Camera, thin_lens)) X(sizeof(Material)) X(offsetof(Material, ka))               \
  X(offsetof(Material, ior)) X(offsetof(Material, emission)) X(sizeof(Light))                \
  X(sizeof(Emitter)) X(offsetof(Emitter, edge2)) X(offsetof(Emitter, radiance))              \
  X(offsetof(Hit, glow)) X(offsetof(Instance, glow)) X(offsetof(RenderParams, glow_light))   \
  X(offsetof(Light, edge_v)) X(offsetof(Light, kind)) X(offsetof(Light, first_sample))       \
  X(offsetof(Light, spot_exponent)) X(sizeof(Instance)) X(offsetof(Instance, material)) \
  X(offsetof(Instance, shape)) X(offsetof(Instance, cone_r0)) X(sizeof(Mesh))                \
  X(offsetof(Mesh, normals)) X(sizeof(Triangle)) X(offsetof(Triangle, v2))               \
  X(sizeof(TriangleNormals)) X(sizeof(RenderParams)) X(offsetof(RenderParams, ambient))      \
  X(offsetof(RenderParams, light_count)) X(offsetof(RenderParams, epsilon))                  \
  X(offsetof(RenderParams, environment)) X(offsetof(RenderParams, glossy))                     \
  X(offsetof(Light, data)) X(sizeof(BvhNode))                                                \
  X(offsetof(BvhNode, max_z))                                                                \
  X(offsetof(BvhNode, child)) X(offsetof(BvhNode, count))                                    \
  X(offsetof(Hit, u)) X(offsetof(Hit, uv_scale)) X(offsetof(Material, textures))             \
  X(offsetof(Mesh, texcoords)) X(sizeof(TriangleTexcoords)) X(offsetof(RenderParams, cone_spread)) \
  X(sizeof(Texture)) X(offsetof(Texture, color1)) X(offsetof(Texture, offset))               \
  X(offsetof(Texture, kind)) X(offsetof(Texture, levels)) X(offsetof(Texture, octaves))

#define AS_STRING(expr) #expr,
#define AS_HOST_VALUE(expr) static_cast<unsigned>(expr),
#define AS_DEVICE_STORE(expr) "out[n++] = (uint)(" #expr ");\n" +

using namespace clrt::dev;
const std::vector<std::string> kNames = {LAYOUT_FIELDS(AS_STRING)};
const std::vector<unsigned> kHost = {LAYOUT_FIELDS(AS_HOST_VALUE)};

std::string layout_kernel() {
  return std::string(
             "#ifndef offsetof\n#define offsetof(t, m) __builtin_offsetof(t, m)\n#endif\n"
             "#include \"shared/ray.h\"\n#include \"shared/scene.h\"\n#include \"shared/bvh.h\"\n"
             "__kernel void layout(__global uint* out) {\n"
             "  if (get_global_id(0) != 0) return;\n  int n = 0;\n") +
         LAYOUT_FIELDS(AS_DEVICE_STORE) "}\n";
}

struct LayoutArgs {
  static constexpr const char* kName = "layout";
  Global<cl_uint> out;
  CLRT_KERNEL_ARGS(out)
};

}  // namespace

TEST_CASE("shared structures have the same layout on the device and the host", "[layout]") {
  LayoutArgs args;
  args.out = test::allocate<cl_uint>(kHost.size());
  test::run(test::test_program(layout_kernel()), args, 1);
  const std::vector<cl_uint> device = test::download(args.out, kHost.size());
  for (std::size_t i = 0; i < kHost.size(); ++i) {
    INFO(kNames[i]);
    CHECK(device[i] == kHost[i]);
  }
}

// The argument structure of each kernel of the wavefront's stages and of the kernels every
// integrator shares (an integrator's own kernel has its structure in its file), one per kernel, each field
// named as the kernel's parameter and listed once, in order, by CLRT_KERNEL_ARGS. Nothing else
// binds kernel arguments (TypedKernel); tests/kernels/test_bindings.cpp checks each structure
// against its kernel's signature as the device reports it.
#pragma once

#include <limits>

#include "device/kernel_args.hpp"
#include "geometry/device_geometry.hpp"
#include "shared/ray.h"
#include "shared/scene.h"

namespace clrt {

CLRT_DEVICE_TYPE_NAME(dev::Ray, "Ray");
CLRT_DEVICE_TYPE_NAME(dev::ShadowRay, "ShadowRay");
CLRT_DEVICE_TYPE_NAME(dev::Camera, "Camera");
CLRT_DEVICE_TYPE_NAME(dev::Material, "Material");
CLRT_DEVICE_TYPE_NAME(dev::Texture, "Texture");
CLRT_DEVICE_TYPE_NAME(dev::Light, "Light");
CLRT_DEVICE_TYPE_NAME(dev::RenderParams, "RenderParams");

// The camera samples of one wave (kernels/render/camera.h): local pixels [first_pixel, ...) of
// a rectangle of the image whose top-left pixel is (region_x, region_y), rows region_width
// wide, and samples [first_sample, first_sample + pixel_samples) of each.
struct WaveArgs {
  cl_uint region_x = 0, region_y = 0, region_width = 0;
  cl_uint first_pixel = 0;
  cl_uint first_sample = 0, pixel_samples = 1;
  cl_uint sample_count = 0;  // camera samples in the wave

  CLRT_KERNEL_ARGS(region_x, region_y, region_width, first_pixel, first_sample, pixel_samples,
                   sample_count)
};

struct GenerateArgs {
  static constexpr const char* kName = "generate";
  Global<const dev::Camera> camera;
  WaveArgs wave;
  Global<dev::Ray> rays;

  CLRT_KERNEL_ARGS(camera, wave, rays)
};

struct IntersectArgs {
  static constexpr const char* kName = "intersect";
  SceneArgs scene;
  Global<const dev::RenderParams> params;
  Global<const dev::Ray> rays;
  cl_uint count = 0;
  Global<dev::Hit> hits;

  CLRT_KERNEL_ARGS(scene, params, rays, count, hits)
};

// What both shading kernels read: the frame's tables and the pass's rays and hits.
struct ShadeInputs {
  Global<const dev::RenderParams> params;
  Global<const dev::Material> materials;
  Global<const dev::Texture> textures;
  Global<const cl_uint> texels;
  Global<const dev::Light> lights;
  Global<const dev::Ray> rays;
  Global<const dev::Hit> hits;

  CLRT_KERNEL_ARGS(params, materials, textures, texels, lights, rays, hits)
};

// What both write, in each ray's own slots (kernels/shade.cl).
struct ShadeOutputs {
  Global<dev::f4> colour;
  Global<dev::ShadowRay> shadow_slots;
  Global<cl_uint> shadow_flags;
  Global<dev::Ray> spawn_slots;
  Global<cl_uint> spawn_flags;

  CLRT_KERNEL_ARGS(colour, shadow_slots, shadow_flags, spawn_slots, spawn_flags)
};

struct ShadeArgs {
  static constexpr const char* kName = "shade";
  ShadeInputs in;
  cl_uint first = 0, count = 0;
  ShadeOutputs out;

  CLRT_KERNEL_ARGS(in, first, count, out)
};

// shade's work for the rays of one shading class, in the order the class lists them.
struct ShadeSortedArgs {
  static constexpr const char* kName = "shade_sorted";
  ShadeInputs in;
  cl_uint first = 0;
  Global<const cl_uint4> order;
  Global<const cl_uint> class_count;  // left on the device by the compaction
  ShadeOutputs out;

  CLRT_KERNEL_ARGS(in, first, order, class_count, out)
};

struct ClassifyHitsArgs {
  static constexpr const char* kName = "classify_hits";
  Global<const dev::Material> materials;
  Global<const dev::Hit> hits;
  cl_uint first = 0, count = 0;
  cl_uint stride = 0;  // between the classes' flag sets, in flags
  Global<cl_uint4> indices;
  Global<cl_uint> flags;

  CLRT_KERNEL_ARGS(materials, hits, first, count, stride, indices, flags)
};

struct ShadowArgs {
  static constexpr const char* kName = "shadow";
  SceneArgs scene;
  Global<const dev::RenderParams> params;
  Global<const dev::ShadowRay> shadows;
  Global<const cl_uint> count;  // left on the device by the compaction
  Global<dev::f4> visible;

  CLRT_KERNEL_ARGS(scene, params, shadows, count, visible)
};

struct GatherShadowsArgs {
  static constexpr const char* kName = "gather_shadows";
  Global<const dev::ShadowRay> shadows;
  Global<const dev::f4> visible;
  Global<const cl_uint> count;
  Global<dev::f4> colour;

  CLRT_KERNEL_ARGS(shadows, visible, count, colour)
};

struct AccumulateSamplesArgs {
  static constexpr const char* kName = "accumulate_samples";
  Global<const dev::Ray> rays;
  Global<const dev::f4> colour;
  cl_uint count = 0;
  Global<dev::f4> sample_colour;

  CLRT_KERNEL_ARGS(rays, colour, count, sample_colour)
};

struct ResolveArgs {
  static constexpr const char* kName = "resolve";
  Global<const dev::f4> sample_colour;
  cl_uint samples = 0, first_sample = 0, pixel_count = 0;
  cl_float max_sample_value = std::numeric_limits<float>::infinity();  // no clamp
  Global<dev::f4> pixels;

  CLRT_KERNEL_ARGS(sample_colour, samples, first_sample, pixel_count,
                   max_sample_value, pixels)
};

struct CompactCountArgs {
  static constexpr const char* kName = "compact_count";
  Global<const cl_uint> flags;
  cl_uint n = 0, chunk = 0;
  Global<cl_uint> chunk_counts;

  CLRT_KERNEL_ARGS(flags, n, chunk, chunk_counts)
};

struct CompactScanArgs {
  static constexpr const char* kName = "compact_scan";
  Global<cl_uint> chunk_counts;
  cl_uint chunks = 0;
  Global<cl_uint> total;

  CLRT_KERNEL_ARGS(chunk_counts, chunks, total)
};

struct CompactScatterArgs {
  static constexpr const char* kName = "compact_scatter";
  Global<const cl_uint4> in;
  Global<const cl_uint> flags;
  cl_uint n = 0, chunk = 0, words = 0;
  Global<const cl_uint> chunk_offsets;
  Global<cl_uint4> out;
  cl_uint capacity = 0;

  CLRT_KERNEL_ARGS(in, flags, n, chunk, words, chunk_offsets, out, capacity)
};

struct CountRayKindsArgs {
  static constexpr const char* kName = "count_ray_kinds";
  Global<const dev::Ray> rays;
  cl_uint count = 0, chunk = 0;
  Global<cl_uint> partial;

  CLRT_KERNEL_ARGS(rays, count, chunk, partial)
};

struct FoldRayCountsArgs {
  static constexpr const char* kName = "fold_ray_counts";
  Global<const cl_uint> rows;
  cl_uint row_count = 0, chunk = 0;
  Global<cl_uint> partial;

  CLRT_KERNEL_ARGS(rows, row_count, chunk, partial)
};

struct AddRayKindsArgs {
  static constexpr const char* kName = "add_ray_kinds";
  Global<const cl_uint> partial;
  cl_uint rows = 0, pass = 0;
  Global<cl_ulong> staging;

  CLRT_KERNEL_ARGS(partial, rows, pass, staging)
};

struct AddShadowRaysArgs {
  static constexpr const char* kName = "add_shadow_rays";
  Global<const cl_uint> count;
  cl_uint pass = 0;
  Global<cl_ulong> staging;

  CLRT_KERNEL_ARGS(count, pass, staging)
};

struct CommitRayCountsArgs {
  static constexpr const char* kName = "commit_ray_counts";
  cl_uint entries = 0;
  Global<cl_ulong> staging;
  Global<cl_ulong> totals;

  CLRT_KERNEL_ARGS(entries, staging, totals)
};

}  // namespace clrt

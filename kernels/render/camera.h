/* Camera rays of a wave. A wave is a run of local pixels [first_pixel, ...) of a rectangle of
 * the image (the region) whose top-left pixel is (region_x, region_y) and whose rows are
 * region_width pixels wide, and a run of each pixel's samples [first_sample, first_sample +
 * pixel_samples) (a round: src/render/sample_rounds.hpp). Camera ray `index` of the wave is
 * sample first_sample + index % pixel_samples of local pixel first_pixel + index /
 * pixel_samples, so a wave's queue starts sorted by pixel and sample. */
#ifndef CLRT_RENDER_CAMERA_H
#define CLRT_RENDER_CAMERA_H

#include "common.h"
#include "sobol.h"

/* The stratified sampler: one sample goes through the pixel centre; more are stratified with one
 * jitter per cell of the camera's grid, and each ray's stream is a hash of the sample and its
 * branches. The Sobol sampler (path mode) jitters every sample by its pixel's scrambled Sobol
 * points, and the ray carries the pixel's stream (render/path_step.h). Every ray carries its camera
 * sample's index, which its children keep.
 * Streams are keyed by the pixel's place in the whole image, never in the region or the wave,
 * so every region of a frame has the full render's bits. */
CLRT_INLINE Ray wave_camera_ray(const Camera* cam, uint region_x, uint region_y, uint region_width,
                                uint first_pixel, uint first_sample, uint pixel_samples,
                                uint index) {
  const uint in_region = first_pixel + index / pixel_samples;
  const uint k = first_sample + index % pixel_samples;
  const uint x = region_x + in_region % region_width;
  const uint y = region_y + in_region / region_width;
  const bool sobol = cam->sampler == CLRT_SAMPLER_SOBOL;
  const uint pixel = y * cam->width + x;
  const uint path = sobol ? pixel_stream(cam->seed, pixel) : camera_path(cam->seed, pixel, k);
  const float2 offset =
      sobol ? sobol_sample(sample_key(path, 0u, CLRT_CAMERA_JITTER), k)
      : cam->samples == 1 ? (float2)(0.5f, 0.5f)
                          : stratified(k, cam->grid_u, cam->grid_v, jitter2(path, CLRT_CAMERA_JITTER));
  const float3 dir = xyz(cam->corner) + ((float)x + offset.x) * xyz(cam->pixel_dx) +
                     ((float)y + offset.y) * xyz(cam->pixel_dy);
  Ray ray;
  vstore3(xyz(cam->eye), 0, ray.origin);
  ray.radiance_scale = 1.0f;
  vstore3(normalize3(dir), 0, ray.dir);
  ray.sample_index = k;
  vstore3((float3)(1.0f), 0, ray.weight);
  ray.pdf = 0.0f;
  ray.sample = index;
  ray.depth = 0u;
  ray.path = path;
  ray.kind = CLRT_RAY_CAMERA;
  return ray;
}

#endif

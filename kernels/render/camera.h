/* Camera rays of a wave. A wave is a run of local pixels [first_pixel, ...) of a rectangle of
 * the image (the region) whose top-left pixel is (region_x, region_y) and whose rows are
 * region_width pixels wide, and a run of each pixel's samples [first_sample, first_sample +
 * pixel_samples) (a round: src/render/sample_rounds.hpp). Camera ray `index` of the wave is
 * sample first_sample + index % pixel_samples of local pixel first_pixel + index /
 * pixel_samples, so a wave's queue starts sorted by pixel and sample. */
#ifndef CLRT_RENDER_CAMERA_H
#define CLRT_RENDER_CAMERA_H

#include "common.h"
#include "random.h"

/* One sample goes through the pixel centre; more are stratified with one jitter per cell of
 * the camera's grid. The random stream is keyed by the pixel's place in the whole image, never
 * in the region or the wave, so every region of a frame has the full render's bits. */
CLRT_INLINE Ray wave_camera_ray(const Camera* cam, uint region_x, uint region_y, uint region_width,
                                uint first_pixel, uint first_sample, uint pixel_samples,
                                uint index) {
  const uint in_region = first_pixel + index / pixel_samples;
  const uint k = first_sample + index % pixel_samples;
  const uint x = region_x + in_region % region_width;
  const uint y = region_y + in_region / region_width;
  const uint path = camera_path(cam->seed, y * cam->width + x, k);
  const float2 offset = cam->samples == 1
                            ? (float2)(0.5f, 0.5f)
                            : stratified(k, cam->grid_u, cam->grid_v, jitter2(path, CLRT_CAMERA_JITTER));
  const float3 dir = xyz(cam->corner) + ((float)x + offset.x) * xyz(cam->pixel_dx) +
                     ((float)y + offset.y) * xyz(cam->pixel_dy);
  Ray ray;
  ray.origin = cam->eye;
  ray.dir = as_f4(normalize3(dir));
  ray.weight = (f4)(1.0f, 1.0f, 1.0f, 0.0f);
  ray.sample = index;
  ray.depth = 0u;
  ray.path = path;
  ray.kind = CLRT_RAY_CAMERA;
  return ray;
}

#endif

/* generate: camera rays for a wave of pixels.
 * In: the camera; the wave's first pixel and its sample count (pixels x samples per pixel).
 * Out: rays[i] for sample i of the wave, i = local pixel * samples + k, so the queue starts
 * sorted by sample. One sample goes through the pixel centre; more are stratified with one
 * jitter per cell of the camera's grid. */
#include "render/common.h"
#include "render/random.h"

__kernel void generate(__global const Camera* camera, uint first_pixel, uint sample_count,
                       __global Ray* rays) {
  const uint i = get_global_id(0);
  if (i >= sample_count) return;
  const Camera cam = *camera;
  const uint pixel = first_pixel + i / cam.samples;
  const uint k = i % cam.samples;
  const uint path = camera_path(cam.seed, pixel, k);
  const float2 offset = cam.samples == 1
                            ? (float2)(0.5f, 0.5f)
                            : stratified(k, cam.grid_u, cam.grid_v, jitter2(path, CLRT_CAMERA_JITTER));
  const float x = (float)(pixel % cam.width) + offset.x;
  const float y = (float)(pixel / cam.width) + offset.y;
  const float3 dir = xyz(cam.corner) + x * xyz(cam.pixel_dx) + y * xyz(cam.pixel_dy);

  Ray ray;
  ray.origin = cam.eye;
  ray.dir = as_f4(normalize(dir));
  ray.weight = (f4)(1.0f, 1.0f, 1.0f, 0.0f);
  ray.sample = i;
  ray.depth = 0u;
  ray.path = path;
  ray.kind = CLRT_RAY_CAMERA;
  rays[i] = ray;
}

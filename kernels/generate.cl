/* generate: the camera rays of a wave (render/camera.h says which pixels and samples).
 * Out: rays[i] = camera sample i of the wave, i < sample_count. */
#include "render/camera.h"

__kernel void generate(__global const Camera* camera, uint region_x, uint region_y,
                       uint region_width, uint first_pixel, uint first_sample,
                       uint pixel_samples, uint sample_count, __global Ray* rays) {
  const uint i = get_global_id(0);
  if (i >= sample_count) return;
  const Camera cam = *camera;
  rays[i] = wave_camera_ray(&cam, region_x, region_y, region_width, first_pixel, first_sample,
                            pixel_samples, i);
}

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
/* A point of the unit disc for u in [0, 1)^2, by the concentric map (Shirley and Chiu 1997): each
 * square about the centre goes to a circle, so strata of the square stay compact on the disc. */
CLRT_INLINE float2 concentric_disc(float2 u) {
  const float sx = 2.0f * u.x - 1.0f, sy = 2.0f * u.y - 1.0f;
  if (sx == 0.0f && sy == 0.0f) return (float2)(0.0f);
  float r, turns, s, c;
  if (fabs(sx) > fabs(sy)) {
    r = sx;
    turns = 0.125f * (sy / sx);
  } else {
    r = sy;
    turns = 0.25f - 0.125f * (sx / sy);
  }
  sincos_turns(turns, &s, &c);
  return (float2)(r * c, r * s);
}

/* The pair that places camera sample k on the lens: the Sobol sampler's own scrambled pair, or
 * a jittered cell of the camera's grid, the cells dealt to the pixel's samples in a shuffled
 * order of the pixel's own so that a sample's place on the lens is not tied to its place in the
 * pixel. */
CLRT_INLINE float2 lens_sample(const Camera* cam, bool sobol, uint pixel, uint path, uint k) {
  if (sobol) return sobol_sample(sample_key(path, 0u, CLRT_LENS_JITTER), k);
  const uint cell = shuffled_index(k, cam->samples, pixel_stream(cam->seed, pixel));
  return stratified(cell, cam->grid_u, cam->grid_v, jitter2(path, CLRT_LENS_JITTER));
}

/* Camera sample k's time within the shutter: the Sobol sampler's own number, or a jittered
 * stratum of the shutter, the strata dealt to the pixel's samples in a shuffled order of their
 * own (as the lens's cells are); the middle of the shutter for a single sample. Drawn from a
 * stream of its own, so a scene without motion renders the bits it rendered without it; a
 * program built for a still scene, where no one reads the time, does not draw it. */
CLRT_INLINE float shutter_time(const Camera* cam, bool sobol, uint pixel, uint path, uint k) {
  if (!CLRT_SCENE_MOVES) return cam->shutter_open;
  float u = 0.5f;
  if (sobol) {
    u = sobol_sample(sample_key(path, 0u, CLRT_TIME_JITTER), k).x;
  } else if (cam->samples > 1u) {
    const uint stratum =
        shuffled_index(k, cam->samples, hash_combine(pixel_stream(cam->seed, pixel), CLRT_TIME_JITTER));
    u = ((float)stratum + jitter2(path, CLRT_TIME_JITTER).x) / (float)cam->samples;
  }
  return (1.0f - u) * cam->shutter_open + u * cam->shutter_close;
}

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
  float3 dir = xyz(cam->corner) + ((float)x + offset.x) * xyz(cam->pixel_dx) +
               ((float)y + offset.y) * xyz(cam->pixel_dy);
  float3 origin = xyz(cam->eye);
  if (cam->thin_lens) {
    /* The ray leaves a point of the lens towards where the pinhole's ray meets the plane in
     * focus, so points on that plane stay sharp. */
    const float2 disc = concentric_disc(lens_sample(cam, sobol, pixel, path, k));
    const float3 on_lens = disc.x * xyz(cam->lens_u) + disc.y * xyz(cam->lens_v);
    origin += on_lens;
    dir = dir * cam->lens_u.w - on_lens;
  }
  Ray ray;
  vstore3(origin, 0, ray.origin);
  ray.radiance_scale = 1.0f;
  vstore3(normalize3(dir), 0, ray.dir);
  ray.sample_cone = CLRT_SAMPLE_CONE(k, 0u); /* a cone of width 0 */
  vstore3((float3)(1.0f), 0, ray.weight);
  ray.pdf = 0.0f;
  ray.sample = index;
  ray.depth_kind = CLRT_DEPTH_KIND(0u, CLRT_RAY_CAMERA);
  ray.path = path;
  ray.time = shutter_time(cam, sobol, pixel, path, k);
  return ray;
}

#endif

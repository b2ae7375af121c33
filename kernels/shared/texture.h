/* Textures as the device sees them: a table of Texture records and one table of 32-bit texel
 * words, which starts with the sRGB decoding table and holds every image's mip levels after it.
 * The lookup and its filter are clrt's own arithmetic on those words (kernels/render/texture.h),
 * not an OpenCL image sampler, whose filtering precision each implementation chooses. */
#ifndef CLRT_SHARED_TEXTURE_H
#define CLRT_SHARED_TEXTURE_H
#include "common.h"

CLRT_SHARED_BEGIN

/* A program built for a scene without textures (-DCLRT_UNTEXTURED, which the host adds when no
 * material has one) computes no texture coordinates at hits and no ray cones, so the compiler
 * drops that code and such scenes run what they ran before textures existed. */
#ifdef CLRT_UNTEXTURED
#define CLRT_SCENE_TEXTURED 0
#else
#define CLRT_SCENE_TEXTURED 1
#endif

/* Material.textures: no texture in that slot. Row 0 of the texture table is never read, so a
 * Material whose fields were zeroed has no textures. */
#define CLRT_NO_TEXTURE 0u

/* The slots of Material.textures: what a texture's value multiplies. */
#define CLRT_TEXTURE_SLOT_COLOR 0u /* the colour C (rgb) */
#define CLRT_TEXTURE_SLOT_KS 1u    /* ks, by the mean of the texel's channels */
#define CLRT_TEXTURE_SLOT_KR 2u    /* kr, likewise */
#define CLRT_TEXTURE_SLOT_KT 3u    /* kt, likewise */
#define CLRT_TEXTURE_SLOTS 4u

#define CLRT_TEXTURE_IMAGE 0u   /* an image with its mip levels */
#define CLRT_TEXTURE_CHECKER 1u /* squares of color0 and color1 */
#define CLRT_TEXTURE_NOISE 2u   /* gradient noise summed over octaves, from color0 to color1 */

#define CLRT_WRAP_REPEAT 0u
#define CLRT_WRAP_CLAMP 1u

#define CLRT_TEXELS_SRGB8 0u /* one word per texel, r | g << 8 | b << 16, sRGB-encoded */
#define CLRT_TEXELS_FLOAT 1u /* three words per texel: linear r, g, b as floats */

/* Texel words [0, CLRT_SRGB_TABLE_WORDS): the linear value of each 8-bit sRGB code, as floats. */
#define CLRT_SRGB_TABLE_WORDS 256u

/* The coarsest mip level is 1x1; 65536 texels on a side make 17 levels. */
#define CLRT_MAX_TEXTURE_LEVELS 17u

typedef struct Texture {
  f4 color0;     /* checker: the squares where floor(s) + floor(t) is even; noise: at -1; w unused */
  f4 color1;     /* checker: the other squares; noise: at +1; w unused */
  float scale[2];  /* the texture's coordinates (s, t) = (u, v) * scale + offset */
  float offset[2];
  u32 kind;        /* CLRT_TEXTURE_* */
  u32 wrap;        /* CLRT_WRAP_*: images only */
  u32 width, height; /* image: level 0's size in texels; level k is max(1, size >> k) */
  u32 levels;        /* image: mip levels, the last one 1x1 */
  u32 texel_format;  /* image: CLRT_TEXELS_* */
  u32 first_word;    /* image: where level 0 starts among the texel words; each level follows the
                        one before, rows from t = 0 (the image's bottom row) up */
  u32 octaves;       /* noise: octaves summed at most (each of twice the frequency, half the
                        amplitude) */
} Texture;
CLRT_CHECK_SIZE(Texture, 80);

CLRT_SHARED_END

#endif

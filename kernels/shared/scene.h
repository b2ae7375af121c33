/* The scene as the device sees it: camera, materials, lights, instances and triangle meshes. */
#ifndef CLRT_SHARED_SCENE_H
#define CLRT_SHARED_SCENE_H
#include "common.h"
#include "texture.h"

CLRT_SHARED_BEGIN

/* How camera samples, and the random numbers of the rays that follow them, are drawn. */
#define CLRT_SAMPLER_STRATIFIED 0u /* Whitted modes: a jittered grid, hashed streams */
#define CLRT_SAMPLER_SOBOL 1u      /* path mode: scrambled Sobol samples (render/sobol.h) */

typedef struct Camera {
  f4 eye;       /* xyz; w unused */
  f4 corner;    /* direction (not unit) through the top-left corner of pixel (0, 0); w unused */
  f4 pixel_dx;  /* change of that direction per pixel to the right; w unused */
  f4 pixel_dy;  /* change per pixel downwards; w unused */
  /* A thin lens (thin_lens != 0): the lens's radius times the unit right and down vectors of the
   * image; lens_u.w scales a pixel's direction above to the point where it meets the plane in
   * focus (the focus distance over the focal length in pixels). Zero for a pinhole. */
  f4 lens_u;
  f4 lens_v;    /* w unused */
  u32 width, height;
  u32 samples;          /* camera samples per pixel */
  u32 grid_u, grid_v;   /* stratification grid: grid_u * grid_v == samples */
  u32 seed;
  u32 sampler;          /* CLRT_SAMPLER_* */
  u32 thin_lens;        /* 1: rays leave the lens (lens_u, lens_v); 0: all leave the eye */
  float shutter_open;   /* each camera sample's time is drawn in [shutter_open, shutter_close] */
  float shutter_close;
  u32 pad[2];
} Camera;
CLRT_CHECK_SIZE(Camera, 144);

typedef struct Material {
  f4 color;    /* rgb surface colour; w unused */
  float ka, kd, ks, shininess;
  float kr, kt, ior, pad;
  f4 emission; /* rgb radiance leaving the front side (the normal's); w 1 if any channel is not 0 */
  u32 textures[CLRT_TEXTURE_SLOTS]; /* per CLRT_TEXTURE_SLOT_*: the row of the texture table
                                       whose value multiplies that term, or CLRT_NO_TEXTURE (0) */
} Material;
CLRT_CHECK_SIZE(Material, 80);

/* The light kinds the device knows, one row X(KIND, name) for each device file
 * kernels/render/lights/name.h, whose name_light_* functions sample it, say whether it reads
 * random numbers, and find where a ray crosses it (kernels/render/lights.h dispatches over these
 * rows). The build writes the list from that folder (tools/cmake/KindLists.cmake); the rows
 * number the kinds CLRT_LIGHT_KIND. The reader's row for the kind is in
 * src/scene/light_kinds.cpp. */
#include "shared/light_kinds.h"
#define CLRT_LIGHT_KIND_VALUE(KIND, name) CLRT_LIGHT_##KIND,
enum { CLRT_LIGHT_KINDS(CLRT_LIGHT_KIND_VALUE) CLRT_LIGHT_KIND_COUNT };
#undef CLRT_LIGHT_KIND_VALUE

/* Non-ambient lights only: ambient lights are summed into RenderParams.ambient. Two kinds come
 * from no `light` command: path mode's glow light (CLRT_LIGHT_GLOW, kernels/render/lights/glow.h),
 * made of the scene's glowing geometry, and the environment (CLRT_LIGHT_ENVIRONMENT,
 * lights/environment.h), which every mode reads for the rays that escape and path mode samples.
 * Their tables (the emitter rows, the environment's texels) follow the records in the same
 * buffer, `data` 16-byte units after their record. */
typedef struct Light {
  f4 color;     /* rgb intensity of the whole light; glow: w the emitter table's total power */
  f4 position;  /* point and spot: position; area: corner; w unused */
  f4 direction; /* directional: unit direction of travel; spot: unit axis S; w unused;
                   area: unit normal, w 1 when its edges are perpendicular (a rectangle), else 0 */
  f4 edge_u;    /* area: first edge; w its length */
  f4 edge_v;    /* area: second edge; w its length */
  u32 kind;     /* CLRT_LIGHT_* */
  u32 samples;  /* shadow samples per shading point: 1, or the area light's sample count */
  u32 grid_u, grid_v;  /* area stratification: grid_u * grid_v == samples */
  u32 first_sample;    /* index of this light's first sample among all samples of a shading point */
  float cos_cutoff;    /* spot: cos(angle) */
  float spot_exponent; /* spot */
  u32 data;            /* glow, environment: its table's distance from this record, in f4s */
} Light;
CLRT_CHECK_SIZE(Light, 112);

/* One glowing triangle or sphere in world space: a row of the table from which path mode draws
 * the glow light's samples, a row in proportion to its power (the luminance of its emission times
 * its area). */
typedef struct Emitter {
  f4 origin;   /* triangle: first corner; sphere: centre; w: the table's cumulative share of the
                  power through this row (the last row's is 1) */
  f4 edge1;    /* triangle: second corner - first; w: sphere: radius, triangle: 0 */
  f4 edge2;    /* triangle: third corner - first, cross(edge1, edge2) pointing to its glowing
                  side; w unused */
  f4 radiance; /* rgb emitted from the front; w unused */
} Emitter;
CLRT_CHECK_SIZE(Emitter, 64);

/* RenderParams.glow_light and .environment: no such light. */
#define CLRT_NO_LIGHT 0xffffffffu

/* Instance.glow and Hit.glow: the surface is not in the emitter table; or it is one of the
 * table's triangles (a row the hit does not name). Any other value is a sphere's row. */
#define CLRT_NO_GLOW 0xffffffffu
#define CLRT_GLOW_TRIANGLES 0xfffffffeu

#define CLRT_SHAPE_SPHERE 0u
#define CLRT_SHAPE_PLANE 1u
#define CLRT_SHAPE_CUBE 2u
#define CLRT_SHAPE_CYLINDER 3u
#define CLRT_SHAPE_CONE 4u
#define CLRT_SHAPE_MESH 5u

/* Instance.material_rows of an instance whose material is its every triangle's. A mesh whose
 * triangles have materials of their own (the scene's loose `triangle`s, an OBJ's `usemtl`
 * faces) has rows in triangle_materials, one per triangle in the order Hit.primitive counts;
 * only such meshes have rows (a table for every mesh's triangles was 4 MB per million of them,
 * unread). A row of CLRT_INSTANCE_MATERIAL (a face no library defines) takes the instance's. */
#define CLRT_NO_MATERIAL_ROWS 0xffffffffu
#define CLRT_INSTANCE_MATERIAL 0xffffffffu

/* A canonical shape or a mesh placed by a transform M. The renderer intersects the canonical
 * object with the ray mapped by M^-1 and maps normals by (M^-1)^T, which it reads out of the
 * same rows (kernels/geometry/motion.h): a table of 3M spheres is 144 MB smaller without it. */
typedef struct Instance {
  f4 world_to_object[3]; /* rows 0..2 of M^-1 (row 3 is 0 0 0 1) */
  u32 shape;             /* CLRT_SHAPE_* */
  u32 material;          /* material index (of the faces without one of their own) */
  u32 mesh;              /* CLRT_SHAPE_MESH: index into the mesh table */
  u32 glow;              /* its place in the emitter table (CLRT_NO_GLOW, CLRT_GLOW_TRIANGLES
                            or its sphere's row) */
  float cone_r0, cone_r1; /* CLRT_SHAPE_CONE: radius at y = -1 and at y = +1 */
  u32 motion;             /* CLRT_NO_MOTION, or its row in the motion table; the rows above are
                             then M^-1 at time 0, which only the host reads */
  u32 material_rows;      /* CLRT_SHAPE_MESH: CLRT_NO_MATERIAL_ROWS, or where its mesh's
                             triangle_materials rows start */
} Instance;
CLRT_CHECK_SIZE(Instance, 80);

#define CLRT_NO_MOTION 0xffffffffu

/* A program built for a scene where nothing moves (-DCLRT_STILL_SCENE, which the host adds when
 * the scene has no motion table) treats every instance as still and draws no shutter times, so
 * the compiler drops the motion code and still scenes run what they ran before motion existed. */
#ifdef CLRT_STILL_SCENE
#define CLRT_SCENE_MOVES 0
#else
#define CLRT_SCENE_MOVES 1
#endif

/* A moving instance's two poses, M = T R S at time 0 and at time 1 (a translation, a rotation
 * and a symmetric stretch, the polar decomposition of M's linear part). At time t the device
 * interpolates T and S linearly and R by spherical linear interpolation of its quaternions
 * (geometry/motion.h); times outside [0, 1] hold the nearer pose. */
typedef struct InstanceMotion {
  f4 translation[2];    /* xyz; w unused */
  f4 rotation[2];       /* unit quaternions (x, y, z, w), the second taken on the first's side
                         * (their dot product >= 0), so that the slerp takes the short way */
  f4 stretch_diagonal[2]; /* S00, S11, S22; w unused */
  f4 stretch_off[2];    /* S01, S02, S12; w unused */
  float angle_turns;    /* the angle between the quaternions, in turns; 0 when they are equal */
  float inverse_sine;   /* 1 / sin of that angle */
  u32 pad[2];
} InstanceMotion;
CLRT_CHECK_SIZE(InstanceMotion, 144);

/* A bottom-level model in its own object space; shared by all the instances that use it. */
typedef struct Mesh {
  u32 first_triangle; /* its triangles' numbers, as BVH packets name them, start here */
  u32 triangle_count;
  u32 root_node;      /* root of its bottom-level BVH in the node table */
  u32 normals;        /* CLRT_NO_NORMALS, or where its triangles' rows of triangle_normals start
                         (in the order Hit.primitive counts) */
  u32 texcoords;      /* CLRT_NO_TEXCOORDS, or where its triangles' rows of triangle_texcoords
                         start (in the order Hit.primitive counts) */
  u32 pad[3];
} Mesh;
CLRT_CHECK_SIZE(Mesh, 32);

/* Mesh.normals of a mesh without vertex normals: it is shaded with its faces' normals, and has
 * no rows in triangle_normals (36 bytes a triangle that a mesh without normals would not read). */
#define CLRT_NO_NORMALS 0xffffffffu

/* Mesh.texcoords of a mesh whose triangles have no texture coordinates of their own: each takes
 * (0, 0), (1, 0) and (0, 1) at its corners. */
#define CLRT_NO_TEXCOORDS 0xffffffffu

/* Vertices in the mesh's object space, counter-clockwise seen from the front. */
typedef struct Triangle {
  f4 v0, v1, v2; /* xyz; w unused */
} Triangle;
CLRT_CHECK_SIZE(Triangle, 48);

/* A triangle's unit vertex normals in object space, packed: x, y, z of the first vertex's, then
 * the second's and the third's. As three f4s it took 48 bytes, a third of them padding: 12 MB
 * more per million triangles, read in place by a CPU device. */
typedef struct TriangleNormals {
  float n[9];
} TriangleNormals;
CLRT_CHECK_SIZE(TriangleNormals, 36);

/* A triangle's texture coordinates: u, v of its first corner, then the second's and the third's. */
typedef struct TriangleTexcoords {
  float uv[6];
} TriangleTexcoords;
CLRT_CHECK_SIZE(TriangleTexcoords, 24);

#define CLRT_MODE_TRACE 0u
#define CLRT_MODE_CAST 1u
#define CLRT_MODE_PATH 2u

/* Per-render constants every stage reads. */
typedef struct RenderParams {
  f4 background;      /* rgb; w unused */
  f4 ambient;         /* rgb sum of the ambient lights; w unused */
  u32 light_count;    /* entries in the light table */
  u32 shadow_samples; /* sum of Light.samples: shadow-ray slots per shading point */
  u32 max_depth;
  u32 mode;           /* CLRT_MODE_*: the program's transport model was built for it
                       * (-DCLRT_TRANSPORT); the host's passes follow it */
  float epsilon;
  float max_sample_value; /* a camera sample whose largest channel exceeds it is scaled down to it
                           * before a pixel's samples are summed (--max-sample-value); INFINITY:
                           * never */
  u32 glow_light;         /* the glow light's index in the light table, or CLRT_NO_LIGHT */
  u32 environment;        /* the environment's index in the light table (sampled in path mode,
                           * where it is below light_count), or CLRT_NO_LIGHT: the background */
  u32 glossy;             /* trace mode, --glossy: reflection rays are drawn from the material's
                           * Phong lobe about the mirror direction */
  float cone_spread;      /* the angle a pixel spans at the image's centre, in radians: every
                           * ray's cone widens by it per unit of distance (render/texture_lod.h) */
  u32 pad[2];
} RenderParams;
CLRT_CHECK_SIZE(RenderParams, 80);

CLRT_SHARED_END

#endif

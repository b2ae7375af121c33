// What clrt accepts in a scene, for every scene format's loader (.ray, NFF, OBJ meshes), checked
// while loading and so before any work. The reason for each number is beside it;
// docs/reliability.md has the table.
#pragma once

#include <cstdint>
#include <string>
#include <string_view>

namespace clrt::limits {

// Input files are read whole into memory. The largest scenes shipped are a few MiB of text (100k
// spheres: 4 MiB) and a million-triangle OBJ is about 80 MiB. A mesh file stays below 2^31 bytes
// so that every line and column number fits the int of a SourceLocation. Both are whole MiB, the
// unit every message and document states them in.
constexpr std::uint64_t kMaxSceneFileBytes = std::uint64_t{256} << 20;
constexpr std::uint64_t kMaxMeshFileBytes = std::uint64_t{2047} << 20;
static_assert(kMaxMeshFileBytes <= INT32_MAX);

// The longest .ray command (a triangle or material at full precision) is under 300 bytes, and a
// quoted mesh path at most PATH_MAX (4096): a longer line is not a scene.
constexpr std::size_t kMaxLineBytes = 64 << 10;

// Error messages quote at most this much of a word or line.
constexpr std::size_t kExcerptBytes = 40;

// Every number in a scene file lies within +-kMaxNumber, and every coordinate in world space (and
// every point of the scene seen in an object's own space) within +-kMaxCoordinate. The device
// computes in single precision (largest value 3.4e38); the ray-triangle test multiplies three
// coordinates, so 1e12 keeps every such product (1e36) finite. Triangles at 1e13 vanished
// before this limit.
constexpr double kMaxNumber = 1e12;
constexpr double kMaxCoordinate = 1e12;

// Corners of a concave polygon (NFF p and pp, an OBJ face). Ear clipping takes time that grows
// with the square of the corner count (4096 corners: a few milliseconds; 100k: 20-40 s), so a
// larger polygon is refused unless it is convex, which a fan cuts in time linear in its corners
// whatever their count.
constexpr std::size_t kMaxConcavePolygonCorners = 4096;

// Image sides and pixel count. The device numbers pixels and samples in 32 bits, and the host
// holds about 28 bytes per pixel (linear floats, 8-bit copy, encoded file): 2^28 pixels
// (16384 x 16384) is 7 GiB.
constexpr std::int64_t kMaxImageSide = 65536;
constexpr std::int64_t kMaxPixels = std::int64_t{1} << 28;

// The narrowest field of view, in degrees. The device builds a camera ray as f F + x R + y U in
// single precision, with the focal length f = width / (2 tan(fov / 2)) in pixels, and normalises
// it: at this fov and the widest image, f is 4e15 and its square far from overflowing (at 1e-17
// degrees it overflowed and every ray was NaN).
constexpr double kMinFovDegrees = 1e-9;

// An area light's edges must be further from parallel than this sine of the angle between them:
// nearer, their cross product (the light's normal, as long as its area), taken by the device in
// single precision, loses its direction.
constexpr double kMinAreaLightEdgeSine = 1e-4;

// Camera samples per pixel, and maximum ray depth: the command line's caps, the same in a file.
constexpr std::int64_t kMaxSamples = 65536;
constexpr std::int64_t kMaxDepth = 65536;

// Shadow-ray samples of one area light (a 256 x 256 grid), and of all lights together at one
// shading point: each shading point holds one slot per sample on the device (148 bytes with its
// flag, queue entry and visibility), so 2^20 slots are 148 MiB even when a queue shades one ray
// at a time, and the sum stays far from 32 bits (it once wrapped and the kernel wrote past
// its buffer).
constexpr std::int64_t kMaxLightSamples = 65536;
constexpr std::int64_t kMaxShadowSamples = std::int64_t{1} << 20;

}  // namespace clrt::limits

namespace clrt {

struct LightSpec;

// Shadow-ray samples `light` takes at each shading point: 0 for ambient light, the sample count
// of an area light, else 1.
std::int64_t shadow_samples(const LightSpec& light);

// `value` in at most 3 significant digits for messages: 1e12, 1.5e13, 0.25.
std::string short_number(double value);

// `text` as an error message may quote it: whole when short, else its first
// limits::kExcerptBytes bytes, "...", and its length.
std::string excerpt(std::string_view text);

}  // namespace clrt

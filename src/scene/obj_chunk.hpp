// One slice of an OBJ file's lines parsed on its own, so that the slices of a large file can be
// parsed side by side: its vertices, texture coordinates, normals and triangle corners, or its
// first malformed line.
#pragma once

#include <array>
#include <atomic>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "math/vec3.hpp"

namespace clrt {

// A place in a slice: lines count from 0 at the slice's first line, columns (bytes) from 1.
struct ObjPlace {
  std::size_t line = 0;
  std::size_t column = 1;
};

struct ObjProblem {
  ObjPlace where;
  std::string message;
};

// Marks a corner without a normal (or texture coordinate) in ObjCornerRefs::index (no relative
// index reaches it).
constexpr std::int32_t kObjNoIndex = INT32_MIN;

// The tables a face corner indexes into, in the order it names them (v/vt/vn).
enum class ObjTable { Position, Texcoord, Normal };

// Per triangle corner, an index from 0 into the whole file's positions (or texture coordinates,
// or normals). A relative index (negative in the file) counts back from the elements read so far,
// of which a slice knows only its own: it is stored counted from the slice's first element (so it
// may be negative) and listed in `relative`, for resolve_obj_indices (obj_index_check.hpp) to
// complete.
struct ObjCornerRefs {
  std::vector<std::int32_t> index;
  std::vector<std::uint32_t> relative;  // the entries of `index` that are counted from the slice
};

// A face of more than three corners: read as the fan (0, k, k + 1), its triangles' corners from
// `first_corner` on; obj_polygons.hpp cuts it along its shape once every position is known.
struct ObjPolygon {
  std::size_t first_corner;
  std::size_t corners;
  std::size_t line;  // in the slice, from 0
};

// `usemtl NAME`: the slice's triangles from `first_triangle` on, up to the next run's, use NAME.
struct ObjMaterialRun {
  std::size_t first_triangle;
  std::string name;
  ObjPlace where;  // of the name
};

// `mtllib FILE`, as written.
struct ObjLibraryRef {
  std::string path;
  ObjPlace where;  // of the path
};

struct ObjChunk {
  std::vector<Vec3> positions;   // `v x y z`, as single-precision values
  std::vector<std::array<float, 2>> texcoords;  // `vt u [v [w]]`: (u, v), v 0 when missing
  std::vector<Vec3> normals;     // `vn x y z`
  ObjCornerRefs corners;         // three per triangle
  ObjCornerRefs corner_normals;  // likewise; kObjNoIndex for a corner that names no normal
  // Likewise for texture coordinates, but empty until the slice's first corner that names one, so
  // that a file without any costs nothing.
  ObjCornerRefs corner_texcoords;
  std::vector<ObjPolygon> polygons;
  std::vector<ObjMaterialRun> material_runs;
  std::vector<ObjLibraryRef> libraries;
  bool every_corner_has_normal = true;
  std::size_t lines = 0;              // line ends in the slice
  std::optional<ObjProblem> problem;  // the first malformed line: parsing stopped there

  std::uint64_t bytes() const;  // what its tables hold, reserved room included
};

// The memory the slices of one file may take together, shared by the threads that parse them.
struct ObjMemoryMeter {
  std::uint64_t available = UINT64_MAX;
  std::string source;  // which limit `available` is, for the message
  std::atomic<std::uint64_t> used{0};
};

// Parses `text`, whole lines of an OBJ file. Lines other than v, vn, vt, f, usemtl and mtllib
// (o, g, s, ...) and anything from a word starting with '#' to the line's end are ignored. Every
// few thousand lines the chunk's growth is added to `meter`; parsing stops with a problem at the
// line where the meter passes what is available (in this slice or another).
ObjChunk parse_obj_chunk(std::string_view text, ObjMemoryMeter& meter);

// Triangle corner `corner` of the slice `text` as the file spells it: where its word is, its
// position, texture coordinate and normal index as written (0: none), and how many of each the
// slice held before its line. `corner` must be one that parse_obj_chunk returned.
struct ObjCornerSource {
  ObjPlace where;
  std::int64_t position = 0, texcoord = 0, normal = 0;
  std::size_t positions_before = 0, texcoords_before = 0, normals_before = 0;
};
ObjCornerSource find_obj_corner(std::string_view text, std::size_t corner);

}  // namespace clrt

// The second step of reading an OBJ file, once every slice is parsed and the file's counts are
// known: completes each slice's corner indices and checks them against those counts (a face may
// name a vertex that comes later in the file).
#pragma once

#include <cstddef>
#include <optional>

#include "scene/obj_chunk.hpp"

namespace clrt {

struct ObjCounts {
  std::size_t positions = 0, texcoords = 0, normals = 0;
};

// A corner whose index into `table` is out of range.
struct ObjBadCorner {
  std::size_t corner;  // triangle corner in its slice
  ObjTable table;
};

// Makes every index of `chunk`'s corners one into the whole file's tables, given the elements of
// the slices `before` it and the `total`. Returns the chunk's first corner, in file order, with an
// index out of range (the chunk's indices are then incomplete).
std::optional<ObjBadCorner> resolve_obj_indices(ObjChunk& chunk, const ObjCounts& before, const ObjCounts& total);

}  // namespace clrt

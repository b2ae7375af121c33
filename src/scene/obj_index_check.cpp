#include "scene/obj_index_check.hpp"

namespace clrt {
namespace {

void complete_relative(ObjCornerRefs& refs, std::size_t before) {
  for (std::uint32_t i : refs.relative)
    refs.index[i] = static_cast<std::int32_t>(static_cast<std::int64_t>(before) + refs.index[i]);
  refs.relative.clear();
}

bool in_range(std::int32_t index, std::size_t count) {
  return index >= 0 && static_cast<std::size_t>(index) < count;
}

// Whether corner k names no element of `refs`' table, or one of the `count` there are.
bool none_or_in_range(const ObjCornerRefs& refs, std::size_t k, std::size_t count) {
  return refs.index.empty() || refs.index[k] == kObjNoIndex || in_range(refs.index[k], count);
}

}  // namespace

std::optional<ObjBadCorner> resolve_obj_indices(ObjChunk& chunk, const ObjCounts& before, const ObjCounts& total) {
  complete_relative(chunk.corners, before.positions);
  complete_relative(chunk.corner_texcoords, before.texcoords);
  complete_relative(chunk.corner_normals, before.normals);
  const std::vector<std::int32_t>& positions = chunk.corners.index;
  for (std::size_t k = 0; k < positions.size(); ++k) {
    if (!in_range(positions[k], total.positions)) return ObjBadCorner{k, ObjTable::Position};
    if (!none_or_in_range(chunk.corner_texcoords, k, total.texcoords)) return ObjBadCorner{k, ObjTable::Texcoord};
    if (!none_or_in_range(chunk.corner_normals, k, total.normals)) return ObjBadCorner{k, ObjTable::Normal};
  }
  return std::nullopt;
}

}  // namespace clrt

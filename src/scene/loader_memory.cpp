#include "scene/loader_state.hpp"
#include "scene/scene_memory.hpp"

namespace clrt {

std::uint64_t loader_bytes(const LoaderState& s) { return s.text_bytes + estimated_scene_bytes(s.scene); }

void check_loader_memory(const LoaderState& s, const SourceLocation& where) {
  check_scene_memory(loader_bytes(s), s.memory, where);
}

}  // namespace clrt

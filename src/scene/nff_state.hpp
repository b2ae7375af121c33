// What the NFF loader keeps while it reads a file, and the table of its entities' handlers.
#pragma once

#include <cstddef>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "scene/command_args.hpp"
#include "scene/loader_state.hpp"

namespace clrt {

struct NffState {
  LoaderState loader;  // the scene, the current material (`f`), where the camera was set
  // A view (v) is followed by its parts in a fixed order: the index of the part expected next,
  // or -1 outside the view.
  int view_part = -1;
  std::optional<SourceLocation> view_at;  // the v entity: a file has exactly one
  double angle_degrees = 0;               // NFF's angle, until `resolution` turns it into a fov
  std::vector<std::size_t> uncoloured_lights;  // into scene.lights: their intensity needs the count
  std::map<int, int> patch_mesh;  // material -> index into scene.meshes of its `pp` patches
};

// Each handler gets one entity: its name and every number up to the next entity.
using NffHandler = void (*)(NffState&, const CommandArgs&);
using NffTable = std::map<std::string, NffHandler>;

void add_nff_view_entities(NffTable& table);     // v and its parts (from ... resolution)
void add_nff_look_entities(NffTable& table);     // b, l, f
void add_nff_shape_entities(NffTable& table);    // s, c
void add_nff_polygon_entities(NffTable& table);  // p, pp

// Called before every entity's handler: inside a view only its next part may come, and the
// parts may come nowhere else.
void advance_view(NffState& s, const CommandArgs& a);
// After the last entity (`end` is just past the file's last word): the view must be there, whole.
void finish_view(const NffState& s, const SourceLocation& end);
// After the last entity: lights written without a colour share an intensity that depends on how
// many lights there are.
void finish_lights(NffState& s);

}  // namespace clrt

#include "scene/command_table.hpp"

namespace clrt {

const CommandTable& command_table() {
  static const CommandTable table = [] {
    CommandTable t;
    add_camera_commands(t);
    add_environment_command(t);
    add_material_commands(t);
    add_texture_commands(t);
    add_transform_commands(t);
    add_object_commands(t);
    add_light_commands(t);
    return t;
  }();
  return table;
}

}  // namespace clrt

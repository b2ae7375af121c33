// Maps each .ray command name (lower case) to the function that applies it.
#pragma once

#include <map>
#include <string>

#include "scene/command_args.hpp"
#include "scene/loader_state.hpp"

namespace clrt {

using CommandHandler = void (*)(LoaderState&, const CommandArgs&);
using CommandTable = std::map<std::string, CommandHandler>;

// Each command family adds its own names.
void add_camera_commands(CommandTable& table);
void add_environment_command(CommandTable& table);
void add_material_commands(CommandTable& table);
void add_texture_commands(CommandTable& table);
void add_transform_commands(CommandTable& table);
void add_object_commands(CommandTable& table);
void add_light_commands(CommandTable& table);

const CommandTable& command_table();

}  // namespace clrt

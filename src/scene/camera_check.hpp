// Camera rules that can only be checked once the whole file has been read.
#pragma once

#include "scene/loader_state.hpp"

namespace clrt {

// Throws SceneError if eye equals lookat or up is parallel to the view direction, located at
// the latest of the commands that set the vectors involved.
void check_camera(const LoaderState& state);

}  // namespace clrt

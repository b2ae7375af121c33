// The SDL window: the only code of clrt-view that talks to SDL. It maps keys and the mouse onto
// controls.hpp and shows what view_layout.hpp composes.
#pragma once

#include <optional>

#include "controls.hpp"
#include "preview_feed.hpp"
#include "readout.hpp"

namespace clrt::view {

// Runs until the window is closed or q is pressed, showing `state` at `zoom` (without one: the
// zoom that fits the screen, fitting_zoom()); `feed`, when given, fills picture A as the render
// comes. Returns the exit status (1 when no window could be opened, said on stderr).
int run_window(ViewSources& sources, const ViewNames& names, ViewState state,
               std::optional<double> zoom, Playback playback, PreviewFeed* feed);

}  // namespace clrt::view

// The window's title: what is shown, the tone settings, and the pixel under the mouse with its
// values in every picture (linear floats, as the file holds them, before exposure and gamma).
#pragma once

#include <optional>
#include <string>

#include "view_layout.hpp"

namespace clrt::view {

struct ViewNames {
  std::string a, b;  // b empty without a second image
};

// "a.pfm | frame 2/3 paused | exposure +1.0 gamma 2.2 | (3, 4) A 0.5 0.25 0.125 B ...".
std::string readout_text(const ViewNames& names, const ViewSources& sources,
                         const ViewState& state, bool playing, std::optional<PixelHit> hit);

}  // namespace clrt::view

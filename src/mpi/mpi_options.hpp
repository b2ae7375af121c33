// The options clrt-mpi adds to clrt's and leaves out: --tile WxH, the size of the tiles the
// ranks are dealt, and no animation.
#pragma once

#include <cstdint>

#include "cli/options.hpp"

namespace clrt::mpi {

struct TileSize {
  std::uint32_t width = 128, height = 128;
};

// clrt-mpi's command line: clrt's options but the animation's (it renders one image), and
// --tile WxH into `tile`.
ProgramOptions mpi_program_options(TileSize& tile);

}  // namespace clrt::mpi

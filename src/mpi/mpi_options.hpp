// The options clrt-mpi adds to clrt's: --tile WxH, the size of the tiles the ranks are dealt.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace clrt::mpi {

struct TileSize {
  std::uint32_t width = 128, height = 128;
};

// Takes `--tile WxH` (or --tile=WxH) out of `args`; the rest are clrt's. Throws UsageError for
// a malformed size.
TileSize take_tile_option(std::vector<std::string>& args);

}  // namespace clrt::mpi

// One image rendered across the ranks of an MPI job, tile by tile. Tiles are dealt dynamically:
// a rank asks for the next tile by sending the pixels of the one it finished, so an uneven scene
// stays balanced; rank 0 deals them from a thread of its own and renders tiles too. A tile is a
// rectangle of the image rendered as a region, so each pixel has the bits of a single render.
#pragma once

#include <cstdint>
#include <vector>

#include "image/image.hpp"
#include "mpi/mpi_session.hpp"
#include "render/pixel_rect.hpp"
#include "render/progress.hpp"
#include "render/renderer.hpp"

namespace clrt::mpi {

// `region` cut into tiles of at most width x height, row by row.
std::vector<PixelRect> cut_into_tiles(const PixelRect& region, std::uint32_t width,
                                      std::uint32_t height);

struct FarmStats {
  std::vector<std::uint64_t> tiles, pixels, bytes;  // per rank: done, and pixel bytes sent
};

// On every rank: renders its share of `tiles` with `renderer`. On rank 0, returns the region's
// image (8-bit RGBA when `eight_bit`, else floats) with every tile in place, and `stats` for
// every rank; elsewhere an empty image. A rank that fails ends the job (exit 1), its message
// printed by rank 0.
AnyImage farm_tiles(const Session& session, Renderer& renderer, const PixelRect& region,
                    const std::vector<PixelRect>& tiles, bool eight_bit, FarmStats& stats,
                    Progress& progress);

}  // namespace clrt::mpi

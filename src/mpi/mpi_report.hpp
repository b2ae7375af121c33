// What --stats says of an MPI render: per rank, the tiles and pixels it rendered, the bytes it
// sent (the scene's files from rank 0, tiles' pixels from the others) and its own statistics
// (rays by kind, kernel times, BVH and kernel build), and the job's times.
#pragma once

#include <cstdint>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "mpi/tile_farm.hpp"

namespace clrt::mpi {

struct RunReport {
  explicit RunReport(int rank_count) : ranks(rank_count) {}
  int ranks;
  std::uint64_t scene_bytes_sent = 0;  // by rank 0, to all the others
  FarmStats farm;
  double render_seconds = 0, total_seconds = 0;

  // `rank_stats`: each rank's RenderStats as JSON text, in rank order.
  nlohmann::json to_json(const std::vector<std::string>& rank_stats) const;
  std::string to_text(const std::vector<std::string>& rank_stats) const;
};

}  // namespace clrt::mpi

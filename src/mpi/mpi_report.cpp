#include "mpi/mpi_report.hpp"

#include <iomanip>
#include <sstream>

namespace clrt::mpi {

nlohmann::json RunReport::to_json(const std::vector<std::string>& rank_stats) const {
  nlohmann::json j;
  j["ranks"] = ranks;
  j["scene_bytes_sent"] = scene_bytes_sent;
  j["seconds"] = {{"render", render_seconds}, {"total", total_seconds}};
  std::uint64_t rays = 0;
  j["per_rank"] = nlohmann::json::array();
  for (int r = 0; r < ranks; ++r) {
    const nlohmann::json stats = nlohmann::json::parse(rank_stats[static_cast<std::size_t>(r)]);
    rays += stats["rays"]["total"].get<std::uint64_t>();
    j["per_rank"].push_back({{"rank", r},
                             {"tiles", farm.tiles[static_cast<std::size_t>(r)]},
                             {"pixels", farm.pixels[static_cast<std::size_t>(r)]},
                             {"pixel_bytes_sent", farm.bytes[static_cast<std::size_t>(r)]},
                             {"stats", stats}});
  }
  j["rays"] = rays;
  j["mrays_per_second"] = render_seconds > 0 ? static_cast<double>(rays) / render_seconds / 1e6 : 0;
  return j;
}

std::string RunReport::to_text(const std::vector<std::string>& rank_stats) const {
  const nlohmann::json j = to_json(rank_stats);
  std::ostringstream out;
  out << std::fixed << std::setprecision(3);
  out << "ranks:         " << ranks << ", render " << render_seconds << " s, total "
      << total_seconds << " s, " << std::setprecision(2) << j["mrays_per_second"].get<double>()
      << " Mrays/s\n"
      << std::setprecision(3);
  out << "scene:         " << scene_bytes_sent << " bytes sent by rank 0 to the others\n";
  out << "per rank:      rank   tiles     pixels  bytes sent       rays  bvh s  build s\n";
  for (const nlohmann::json& r : j["per_rank"])
    out << "               " << std::setw(4) << r["rank"].get<int>() << std::setw(8)
        << r["tiles"].get<std::uint64_t>() << std::setw(11) << r["pixels"].get<std::uint64_t>()
        << std::setw(12) << r["pixel_bytes_sent"].get<std::uint64_t>() << std::setw(11)
        << r["stats"]["rays"]["total"].get<std::uint64_t>() << std::setw(7)
        << r["stats"]["seconds"]["bvh"].get<double>() << std::setw(9)
        << r["stats"]["seconds"]["kernel_build"].get<double>() << "\n";
  return out.str();
}

}  // namespace clrt::mpi

#include "mpi/mpi_options.hpp"

#include <regex>

#include "render/usage_error.hpp"

namespace clrt::mpi {

TileSize take_tile_option(std::vector<std::string>& args) {
  TileSize tile;
  for (std::size_t i = 0; i < args.size(); ++i) {
    std::string value;
    if (args[i] == "--tile" && i + 1 < args.size()) {
      value = args[i + 1];
      args.erase(args.begin() + static_cast<std::ptrdiff_t>(i), args.begin() + static_cast<std::ptrdiff_t>(i) + 2);
    } else if (args[i].rfind("--tile=", 0) == 0) {
      value = args[i].substr(7);
      args.erase(args.begin() + static_cast<std::ptrdiff_t>(i));
    } else {
      continue;
    }
    static const std::regex form("([0-9]{1,5})[xX]([0-9]{1,5})");
    std::smatch m;
    if (!std::regex_match(value, m, form) || std::stoi(m[1]) < 1 || std::stoi(m[2]) < 1)
      throw UsageError("--tile takes WIDTHxHEIGHT in pixels, e.g. 128x128");
    tile = {static_cast<std::uint32_t>(std::stoi(m[1])), static_cast<std::uint32_t>(std::stoi(m[2]))};
    --i;
  }
  return tile;
}

}  // namespace clrt::mpi

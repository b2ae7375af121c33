#include "mpi/mpi_options.hpp"

#include <CLI/CLI.hpp>

#include <regex>

namespace clrt::mpi {

ProgramOptions mpi_program_options(TileSize& tile) {
  ProgramOptions program;
  program.name = "clrt-mpi";
  program.animation = false;
  program.preview = false;
  program.add_own_options = [&tile](CLI::App& app) {
    app.add_option_function<std::string>(
        "--tile",
        [&tile](const std::string& value) {
          static const std::regex form("([0-9]{1,5})[xX]([0-9]{1,5})");
          std::smatch m;
          if (!std::regex_match(value, m, form) || std::stoi(m[1]) < 1 || std::stoi(m[2]) < 1)
            throw CLI::ValidationError("--tile takes WIDTHxHEIGHT in pixels, e.g. 128x128");
          tile = {static_cast<std::uint32_t>(std::stoi(m[1])),
                  static_cast<std::uint32_t>(std::stoi(m[2]))};
        },
        "the size of the tiles the ranks are dealt, WxH in pixels (default 128x128)");
  };
  return program;
}

}  // namespace clrt::mpi

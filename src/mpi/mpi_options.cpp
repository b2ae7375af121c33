#include "mpi/mpi_options.hpp"

#include <CLI/CLI.hpp>

#include "math/number_fields.hpp"

namespace clrt::mpi {

ProgramOptions mpi_program_options(TileSize& tile) {
  ProgramOptions program;
  program.name = "clrt-mpi";
  program.animation = false;
  program.preview = false;
  program.resume = false;
  program.dump_scene = false;
  program.manual = {
      "docs/scale-out.md",
      {},
      {{"0", "rank 0 wrote the image, or --help or --version"},
       {"1", "a failure at run time on any rank (a rank without a device, a render or a write that "
             "fails): every rank exits 1 and no file is written"},
       {"2", "a usage or scene error, on every rank"}},
      {{"mpirun -np 4 clrt-mpi scenes/reflect.ray -o reflect.png", "one frame across 4 ranks"},
       {"mpirun -np 8 clrt-mpi scenes/cornell.ray --mode path --spp 256 --tile 64x64 -o c.png",
        "smaller tiles, dealt to the ranks as they finish"}}};
  program.add_own_options = [&tile](CLI::App& app) {
    app.add_option_function<std::string>(
        "--tile",
        [&tile](const std::string& value) {
          const auto size = read_number_fields(value, {"#x#", 5, false, true});
          if (!size || (*size)[0] < 1 || (*size)[1] < 1)
            throw CLI::ValidationError("--tile takes WIDTHxHEIGHT in pixels, e.g. 128x128");
          tile = {static_cast<std::uint32_t>((*size)[0]), static_cast<std::uint32_t>((*size)[1])};
        },
        "the size of the tiles the ranks are dealt, WxH in pixels (default 128x128)");
  };
  return program;
}

}  // namespace clrt::mpi

// clrt-mpi under mpirun, as CI runs it (as root, so with Open MPI's root flags set here, and
// oversubscribed: more ranks than cores): the image of N ranks has the bytes of clrt's, with area
// lights, several samples, floats, regions and any tile size; a failing rank, a dead rank and a
// scene error end every rank with one message, the right exit status and no output file.
#include <catch2/catch.hpp>

#include <string>

#include "render_support.hpp"
#include "scratch_dir.hpp"

using namespace clrt;
using namespace clrt::test;

namespace {

const std::string kEnvironment = "OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1";

std::string mpirun(int ranks) {
  return "--oversubscribe -np " + std::to_string(ranks) + " " + quoted(CLRT_MPI_EXE) + " ";
}

CommandResult run_mpi(const std::string& arguments) {
  return run_program(MPIEXEC, arguments, kEnvironment);
}

// How many times `needle` occurs in `text`.
std::size_t count_of(const std::string& text, const std::string& needle) {
  std::size_t n = 0;
  for (std::size_t at = text.find(needle); at != std::string::npos; at = text.find(needle, at + 1))
    ++n;
  return n;
}

}  // namespace

TEST_CASE("N ranks write the bytes clrt writes", "[mpi]") {
  ScratchDir dir;
  struct Case {
    const char* scene;
    std::string options, tile, extension;
  };
  for (const Case& c : {Case{"area.ray", "--spp 4 --seed 2", "16x8", "png"},
                        Case{"area.ray", "--spp 3", "7x5", "pfm"},
                        Case{"reflect.ray", "--pixel-bounds 5,61,3,40", "20x20", "png"},
                        Case{"glass.ray", "", "64x4", "pfm"},
                        // The environment image reaches the ranks from rank 0, as meshes do.
                        Case{"path/environment.ray", "--mode path --spp 2", "16x16", "pfm"},
                        // Each sample's time depends on its pixel and index alone.
                        Case{"path/motion.ray", "--mode path --spp 4", "16x16", "pfm"},
                        // The MTL library reaches the ranks with its OBJ file.
                        Case{"path/mtl.ray", "--mode path --spp 2", "16x16", "pfm"},
                        // The texture images reach the ranks from rank 0, the map_Kd's with its
                        // MTL library.
                        Case{"path/textured.ray", "--mode path --spp 2", "16x16", "pfm"}}) {
    const std::string args = quoted(test_scene(c.scene)) + " -q --resolution 64x48 " + c.options;
    const std::string single = dir.file("single." + c.extension);
    REQUIRE(run_clrt(args + " -o " + single).exit_code == 0);
    for (int ranks : {2, 3}) {
      INFO(c.scene << " " << c.options << ", " << ranks << " ranks");
      const std::string out = dir.file("mpi" + std::to_string(ranks) + "." + c.extension);
      const CommandResult r = run_mpi(mpirun(ranks) + args + " --tile " + c.tile + " -o " + out);
      INFO(r.output);
      REQUIRE(r.exit_code == 0);
      CHECK(file_bytes(out) == file_bytes(single));
    }
  }
}

TEST_CASE("the statistics name every rank's tiles, pixels and bytes", "[mpi]") {
  ScratchDir dir;
  const CommandResult r = run_mpi(mpirun(2) + quoted(test_scene("reflect.ray")) +
                                  " -q --resolution 64x48 --tile 16x16 --stats -o " +
                                  dir.file("out.png"));
  INFO(r.output);
  REQUIRE(r.exit_code == 0);
  CHECK(r.output.find("ranks:         2") != std::string::npos);
  CHECK(r.output.find("bytes sent by rank 0") != std::string::npos);
  CHECK(count_of(r.output, "\n               ") == 2);  // a line per rank
}

TEST_CASE("a scene error is printed once and every rank exits 2", "[mpi]") {
  ScratchDir dir;
  const std::string scene = dir.write("bad.ray", "resolution 10 10\nsphere 0 0 0 -1\n");
  const CommandResult r = run_mpi(mpirun(3) + quoted(scene) + " -o " + dir.file("out.png"));
  INFO(r.output);
  CHECK(r.exit_code == 2);
  CHECK(count_of(r.output, "bad.ray:2:") == 1);
  CHECK(dir.entries() == std::set<std::string>{"bad.ray"});
}

TEST_CASE("a rank without a device stops every rank with exit 1 and no file", "[mpi]") {
  ScratchDir dir;
  const std::string args = quoted(test_scene("reflect.ray")) + " -q -o " + dir.file("out.png");
  // Multiple programs: rank 1 runs where PoCL offers no device.
  const CommandResult r =
      run_mpi("--oversubscribe -np 1 " + quoted(CLRT_MPI_EXE) + " " + args +
              " : -np 1 env POCL_DEVICES=none " + quoted(CLRT_MPI_EXE) + " " + args);
  INFO(r.output);
  CHECK(r.exit_code == 1);
  CHECK(count_of(r.output, "clrt-mpi: error: no OpenCL device") == 1);
  CHECK(dir.entries().empty());
}

TEST_CASE("a rank that dies mid-render ends the job with no file", "[mpi]") {
  ScratchDir dir;
  // Long enough that rank 1 is killed while rendering.
  const std::string args = quoted(test_scene("area.ray")) + " -q --resolution 600x400 --spp 64 -o " +
                           dir.file("out.png");
  const CommandResult r =
      run_mpi("--oversubscribe -np 1 " + quoted(CLRT_MPI_EXE) + " " + args +
              " : -np 1 timeout -s KILL 2 " + quoted(CLRT_MPI_EXE) + " " + args);
  INFO(r.output);
  CHECK(r.exit_code != 0);
  CHECK(dir.entries().empty());
}

TEST_CASE("clrt-mpi names its version and refuses a bad option with exit 2, printed once",
          "[mpi]") {
  const CommandResult version = run_program(CLRT_MPI_EXE, "--version");
  CHECK(version.exit_code == 0);
  CHECK(version.output.find("clrt-mpi, from clrt ") == 0);
  const CommandResult bad = run_mpi(mpirun(2) + "--no-such-option scene.ray");
  INFO(bad.output);
  CHECK(bad.exit_code == 2);
  CHECK(count_of(bad.output, "clrt-mpi: error:") == 1);
  CHECK(count_of(bad.output, "clrt-mpi: error: unknown option --no-such-option\n") == 1);
  const CommandResult tile = run_mpi(mpirun(2) + "--tile 0x5 scene.ray");
  CHECK(tile.exit_code == 2);
  CHECK(count_of(tile.output, "clrt-mpi: error: --tile takes") == 1);
}

TEST_CASE("clrt-mpi --help lists what it accepts: --tile, and no animation options", "[mpi]") {
  const CommandResult help = run_program(CLRT_MPI_EXE, "--help");
  INFO(help.output);
  CHECK(help.exit_code == 0);
  CHECK(help.output.rfind("clrt-mpi: ", 0) == 0);
  for (const char* accepted : {"--tile", "--spp", "--resolution", "--no-write", "-o,--outfile"})
    CHECK(help.output.find(accepted) != std::string::npos);
  for (const char* refused : {"--frames", "--orbit", "--frame-range"}) {
    CHECK(help.output.find(refused) == std::string::npos);
    const CommandResult r = run_mpi(mpirun(2) + refused + " 2 scene.ray");
    CHECK(r.exit_code == 2);
    CHECK(count_of(r.output, "clrt-mpi: error:") == 1);
  }
}

TEST_CASE("clrt-mpi counts its ranks in words: from 1 rank, from 2 ranks", "[mpi]") {
  ScratchDir dir;
  for (const int ranks : {1, 2}) {
    const std::string out = dir.file("count" + std::to_string(ranks) + ".png");
    const CommandResult r = run_mpi(mpirun(ranks) + quoted(test_scene("reflect.ray")) +
                                    " --resolution 16x12 -o " + out);
    INFO(r.output);
    REQUIRE(r.exit_code == 0);
    CHECK(r.output.find(ranks == 1 ? " from 1 rank" : " from 2 ranks") != std::string::npos);
    CHECK(r.output.find(" from 1 ranks") == std::string::npos);
  }
}

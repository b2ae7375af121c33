// The README's usage lines run as written, one after the other in a fresh folder beside the
// repository's scenes: SCENE, SCENES... and OUT stand for scenes/reflect.ray and out.png, and
// each line must exit 0, except where the README itself says what it needs (a GPU for
// --device gpu, a display for clrt-view), and there it must fail for that reason alone.
#include <catch2/catch.hpp>

#include <filesystem>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include "render_support.hpp"
#include "scratch_dir.hpp"
#include "skip_test.hpp"

using namespace clrt::test;

namespace {

// The lines of the usage block (the one that starts with "clrt scenes/reflect.ray"), each its
// command without the description after it.
std::vector<std::string> usage_commands() {
  std::istringstream readme(file_bytes(std::string(CLRT_SOURCE_DIR) + "/README.md"));
  std::vector<std::string> commands;
  bool inside = false;
  for (std::string line; std::getline(readme, line);) {
    if (line.rfind("```", 0) == 0) {
      if (inside) break;
      std::string first;
      std::getline(readme, first);
      inside = first.rfind("clrt scenes/reflect.ray", 0) == 0;
      if (!inside) continue;
      line = first;
    }
    if (!inside) continue;
    // The description starts after two or more spaces.
    static const std::regex description("  +[^ ].*$");
    commands.push_back(std::regex_replace(line, description, ""));
  }
  return commands;
}

std::string with_placeholders_filled(std::string command) {
  for (const auto& [placeholder, value] :
       std::vector<std::pair<std::string, std::string>>{{"SCENES...", "scenes/reflect.ray"},
                                                        {"SCENE", "scenes/reflect.ray"},
                                                        {"OUT", "out.png"}}) {
    for (std::size_t at; (at = command.find(placeholder)) != std::string::npos;)
      command.replace(at, placeholder.size(), value);
  }
  return command;
}

}  // namespace

TEST_CASE("the README's usage lines run as written", "[cli][docs]") {
  const std::vector<std::string> commands = usage_commands();
  REQUIRE(commands.size() > 10);
  ScratchDir dir;
  std::filesystem::create_directory_symlink(std::string(CLRT_SOURCE_DIR) + "/scenes", dir.file("scenes"));
  // The tools as a user's PATH finds them once installed; no display, as on CI; MPI may run as
  // root and with more ranks than cores, as in the MPI tests.
  const std::string environment =
      "-u DISPLAY -u WAYLAND_DISPLAY PATH=" + std::string(CLRT_TOOL_PATH) +
      ":$PATH OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 "
      "OMPI_MCA_rmaps_base_oversubscribe=1";
  bool mpi_missing = false;
  for (const std::string& written : commands) {
    const std::string command = with_placeholders_filled(written);
    INFO(command);
    CHECK(std::regex_search(command, std::regex("\\b[A-Z]{3,}\\b")) == false);  // every placeholder known
    if (command.rfind("mpirun ", 0) == 0 && std::string(CLRT_MPIEXEC).empty()) {
      mpi_missing = true;
      continue;
    }
    const std::string script = dir.write("line.sh", "cd " + quoted(dir.path().string()) + "\n" + command + "\n");
    const CommandResult r = run_program("bash", "--norc " + quoted(script), environment);
    INFO(r.output);
    if (command.find("--device gpu") != std::string::npos && r.exit_code != 0) {
      CHECK(r.exit_code == 1);
      CHECK(r.output.find("no OpenCL device matches --device gpu") != std::string::npos);
    } else if (command.rfind("clrt-view ", 0) == 0) {
      CHECK(r.exit_code == 1);
      CHECK(r.output.find("clrt-view: error: cannot open a window: no display") != std::string::npos);
    } else {
      CHECK(r.exit_code == 0);
    }
  }
  if (mpi_missing) CLRT_SKIP_TEST("MPI is not installed: the README's mpirun line did not run");
}

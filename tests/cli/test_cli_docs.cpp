// Every installed program writes its man page and bash completion from its own parser: each page
// lists every option --help lists (each command's too), points at the program's manual, and the
// completions offer option names, commands and the fixed words of values.
#include <catch2/catch.hpp>

#include <filesystem>
#include <sstream>
#include <string>
#include <vector>

#include "render_support.hpp"
#include "scratch_dir.hpp"

using namespace clrt::test;

namespace {

struct Program {
  std::string name, executable, manual;
};

// The installed programs; clrt-view and clrt-mpi only where SDL2 and MPI were found.
std::vector<Program> programs() {
  std::vector<Program> all = {{"clrt", CLRT_EXE, "docs/cli.md"},
                              {"clrt-img", CLRT_IMG_EXE, "docs/images.md"},
                              {"clrt-experiment", CLRT_EXPERIMENT_EXE, "docs/experiments.md"},
                              {"clrt-make-scenes", CLRT_MAKE_SCENES_EXE, "docs/performance.md"},
                              {"clrt-view", CLRT_VIEW_EXE, "docs/viewer.md"},
                              {"clrt-mpi", CLRT_MPI_EXE, "docs/scale-out.md"}};
  std::vector<Program> built;
  for (const Program& program : all)
    if (!program.executable.empty()) built.push_back(program);
  return built;
}

std::string man_page(const std::string& program) {
  return file_bytes(std::string(CLRT_BINARY_DIR) + "/share/man/man1/" + program + ".1");
}

std::string completion_script(const std::string& program) {
  return std::string(CLRT_BINARY_DIR) + "/share/bash-completion/completions/" + program;
}

// The names at the start of each option line of --help ("  -o,--outfile TEXT ...").
std::vector<std::string> help_option_names(const std::string& executable, const std::string& command) {
  const CommandResult help = run_program(executable, command + " --help");
  REQUIRE(help.exit_code == 0);
  std::vector<std::string> names;
  std::istringstream lines(help.output);
  for (std::string line; std::getline(lines, line);) {
    const std::size_t start = line.find_first_not_of(' ');
    if (start == std::string::npos || line[start] != '-') continue;
    std::istringstream spellings(line.substr(start, line.find(' ', start) - start));
    // A flag's default shows as "--no-plots{false}".
    for (std::string name; std::getline(spellings, name, ',');) names.push_back(name.substr(0, name.find('{')));
  }
  return names;
}

std::string roff_escaped(std::string name) {
  for (std::size_t at = 0; (at = name.find('-', at)) != std::string::npos; at += 2) name.insert(at, "\\");
  return name;
}

// COMPREPLY after completing the last of `words`, as bash would on a tab.
std::string completions(const std::string& program, const std::string& words) {
  std::string function = "_" + program;
  for (char& c : function)
    if (c == '-') c = '_';
  const std::string script = "source '" + completion_script(program) + "'; COMP_WORDS=(" +
                             program + " " + words + "); COMP_CWORD=$((${#COMP_WORDS[@]} - 1)); " +
                             function + "; echo \"${COMPREPLY[*]}\"";
  const CommandResult r = run_program("bash", "--norc -c " + quoted(script));
  REQUIRE(r.exit_code == 0);
  return r.output;
}

}  // namespace

TEST_CASE("each program's man page lists every option its --help lists", "[cli][docs]") {
  for (const Program& program : programs()) {
    INFO(program.name);
    const std::string page = man_page(program.name);
    std::string title = ".TH ";
    for (const char c : program.name) title += c == '-' ? std::string("\\-") : std::string(1, char(std::toupper(c)));
    CHECK(page.rfind(title + " 1 ", 0) == 0);
    // A program of commands has each command's options on the command's --help.
    std::vector<std::string> commands = {""};
    if (program.name == "clrt-img") commands = {"", "convert", "info", "diff", "stitch"};
    for (const std::string& command : commands) {
      if (!command.empty()) CHECK(page.find(".SS " + command + "\n") != std::string::npos);
      for (const std::string& name : help_option_names(program.executable, command)) {
        INFO(command << " " << name);
        CHECK(page.find("\\fB" + roff_escaped(name) + "\\fR") != std::string::npos);
      }
    }
    // The page is installed: it names the installed documentation.
    CHECK(page.find(".SH SEE ALSO\nThe full description of " + roff_escaped(program.name) + ": " +
                    roff_escaped(program.manual) + " in clrt's documentation, " +
                    roff_escaped(std::string(CLRT_INSTALLED_DOC_DIR) + "/" + program.manual)) !=
          std::string::npos);
    CHECK(page.find("\\-\\-write\\-") == std::string::npos);
    // --help, run from the build tree, points at the same manual in the source tree.
    CHECK(run_program(program.executable, "--help").output.find(
              "man " + program.name + ", and " + std::string(CLRT_SOURCE_DIR) + "/" + program.manual + "\n") !=
          std::string::npos);
    CHECK(!file_bytes(std::string(CLRT_SOURCE_DIR) + "/" + program.manual).empty());
  }
}

TEST_CASE("each man page has EXIT STATUS, EXAMPLES and SEE ALSO, with the statuses the program "
          "gives", "[cli][docs]") {
  for (const Program& program : programs()) {
    INFO(program.name);
    const std::string page = man_page(program.name);
    const std::size_t status = page.find(".SH EXIT STATUS\n"), examples = page.find(".SH EXAMPLES\n"),
                      see_also = page.find(".SH SEE ALSO\n");
    REQUIRE(status != std::string::npos);
    REQUIRE(examples != std::string::npos);
    REQUIRE(see_also != std::string::npos);
    CHECK((status < examples && examples < see_also));
    const std::string statuses = page.substr(status, examples - status);
    for (const char* code : {"0", "1", "2"}) CHECK(statuses.find(".TP\n\\fB" + std::string(code) + "\\fR\n") != std::string::npos);
    // The examples run the program (clrt-mpi's under mpirun).
    const std::string listed = page.substr(examples, see_also - examples);
    CHECK(listed.find(roff_escaped(program.name) + " ") != std::string::npos);
    // What the page says of 0 and 2 is what the program returns.
    CHECK(run_program(program.executable, "--version").exit_code == 0);
    CHECK(run_program(program.executable, "--no-such-option").exit_code == 2);
  }
  CHECK(man_page("clrt").find(".TP\n\\fB128 + N\\fR\n") != std::string::npos);
  CHECK(run_program(CLRT_EXE, "no-such-scene.ray").exit_code == 2);
  CHECK(run_program(CLRT_IMG_EXE, "info no-such-image.png").exit_code == 1);
}

TEST_CASE("help output names the documentation where it is for the executable that runs", "[cli][docs]") {
  namespace fs = std::filesystem;
  const ScratchDir scratch;
  // A copy outside the build tree, as an install puts it: without documentation beside it, the
  // configured install's; with share/doc/clrt beside bin/, that one.
  fs::create_directories(scratch.file("bin"));
  const std::string copy = scratch.file("bin/clrt-img");
  fs::copy_file(CLRT_IMG_EXE, copy);
  CHECK(run_program(copy, "--help").output.find(
            "and " + std::string(CLRT_INSTALLED_DOC_DIR) + "/docs/images.md\n") != std::string::npos);
  scratch.write("share/doc/clrt/README.md", "");
  fs::create_directories(scratch.file("share/doc/clrt/docs"));
  const std::string beside = fs::canonical(scratch.file("share/doc/clrt")).string();
  CHECK(run_program(copy, "--help").output.find("and " + beside + "/docs/images.md\n") != std::string::npos);
}

TEST_CASE("docs/cli.md lists every option clrt's --help lists", "[cli][docs]") {
  const std::string cli_md = file_bytes(std::string(CLRT_SOURCE_DIR) + "/docs/cli.md");
  for (const std::string& name : help_option_names(CLRT_EXE, ""))
    if (name.rfind("--", 0) == 0) {
      INFO(name);
      CHECK(cli_md.find("`" + name) != std::string::npos);
    }
}

TEST_CASE("the man page names each group of options once", "[cli][docs]") {
  const std::string page = man_page("clrt");
  for (const char* group : {".SS Scene and image\n", ".SS Rendering\n", ".SS Devices\n",
                            ".SS Output\n", ".SS Animation\n", ".SS Diagnostics\n"}) {
    INFO(group);
    const std::size_t first = page.find(group);
    REQUIRE(first != std::string::npos);
    CHECK(page.find(group, first + 1) == std::string::npos);
  }
  // --preview, added after the animation's options, is listed under Output.
  CHECK(page.find("\\-\\-preview") < page.find(".SS Animation\n"));
}

TEST_CASE("the bash completion completes options and their words", "[cli][docs]") {
  CHECK(completions("clrt", "--sp") == "--spp\n");
  CHECK(completions("clrt", "scene.ray --mode \"\"") == "trace cast path\n");  // in --help's order
  CHECK(completions("clrt", "--integrator w") == "wavefront\n");
  CHECK(completions("clrt", "--frame") == "--frames --frame-range\n");
  CHECK(completions("clrt", "--spp \"\"") == "\n");  // a number: nothing to offer
  CHECK(completions("clrt", "--device \"\"") == "cpu gpu all\n");  // words, not file names
  CHECK(completions("clrt", "--device g") == "gpu\n");
}

TEST_CASE("every program's completion completes its commands and the words of its values",
          "[cli][docs]") {
  CHECK(completions("clrt-img", "\"\"") == "convert info diff stitch\n");
  CHECK(completions("clrt-img", "con") == "convert\n");
  CHECK(completions("clrt-img", "convert a.fsf --fp") == "--fps\n");
  CHECK(completions("clrt-img", "convert a.fsf --tonemap \"\"") == "clamp filmic\n");
  CHECK(completions("clrt-img", "diff --fp") == "\n");  // --fps is convert's, not diff's
  CHECK(completions("clrt-experiment", "--mode \"\"") == "trace cast path\n");
  CHECK(completions("clrt-experiment", "--device \"\"") == "cpu gpu all\n");
  CHECK(completions("clrt-experiment", "--integrator \"\"") == "wavefront megakernel\n");
  CHECK(completions("clrt-make-scenes", "--family \"\"") == "large knob texture-knob\n");
  for (const Program& program : programs())
    if (program.name == "clrt-mpi") {
      CHECK(completions("clrt-mpi", "--ti") == "--tile\n");
      CHECK(completions("clrt-mpi", "--mode p") == "path\n");
    }
}

TEST_CASE("a program asked to write its man page where it cannot says so", "[cli][docs]") {
  const ScratchDir scratch;
  const std::string missing_folder = scratch.file("no-such-folder/clrt-img.1");
  const CommandResult r = run_program(CLRT_IMG_EXE, "--write-man-page " + quoted(missing_folder));
  CHECK(r.exit_code == 1);
  CHECK(r.output.find("clrt-img: error: cannot write ") != std::string::npos);
}

// The man page and the bash completion come from clrt's own parser: the page lists every option
// --help lists, so does docs/cli.md, and the completion completes option names and their fixed
// words.
#include <catch2/catch.hpp>

#include <sstream>
#include <string>
#include <vector>

#include "render_support.hpp"

using namespace clrt::test;

namespace {

// The names at the start of each option line of --help ("  -o,--outfile TEXT ...").
std::vector<std::string> help_option_names() {
  const CommandResult help = run_clrt("--help");
  REQUIRE(help.exit_code == 0);
  std::vector<std::string> names;
  std::istringstream lines(help.output);
  for (std::string line; std::getline(lines, line);) {
    const std::size_t start = line.find_first_not_of(' ');
    if (start == std::string::npos || line[start] != '-') continue;
    std::istringstream spellings(line.substr(start, line.find(' ', start) - start));
    for (std::string name; std::getline(spellings, name, ',');) names.push_back(name);
  }
  return names;
}

std::string roff_escaped(std::string name) {
  for (std::size_t at = 0; (at = name.find('-', at)) != std::string::npos; at += 2) name.insert(at, "\\");
  return name;
}

// COMPREPLY after completing the last of `words`, as bash would on a tab.
std::string completions(const std::string& words) {
  const std::string script = "source '" + std::string(CLRT_BASH_COMPLETION) + "'; COMP_WORDS=(" +
                             words + "); COMP_CWORD=$((${#COMP_WORDS[@]} - 1)); _clrt; "
                             "echo \"${COMPREPLY[*]}\"";
  const CommandResult r = run_program("bash", "--norc -c " + quoted(script));
  REQUIRE(r.exit_code == 0);
  return r.output;
}

}  // namespace

TEST_CASE("the man page and docs/cli.md list every option --help lists", "[cli][docs]") {
  const std::vector<std::string> names = help_option_names();
  REQUIRE(names.size() > 20);
  const std::string man = file_bytes(CLRT_MAN_PAGE);
  const std::string cli_md = file_bytes(std::string(CLRT_SOURCE_DIR) + "/docs/cli.md");
  REQUIRE(man.rfind(".TH CLRT 1", 0) == 0);
  for (const std::string& name : names) {
    INFO(name);
    CHECK(man.find("\\fB" + roff_escaped(name) + "\\fR") != std::string::npos);
    if (name.rfind("--", 0) == 0) CHECK(cli_md.find("`" + name) != std::string::npos);
  }
}

TEST_CASE("the man page names each group of options once", "[cli][docs]") {
  const std::string page = file_bytes(CLRT_MAN_PAGE);
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
  CHECK(completions("clrt --sp") == "--spp\n");
  CHECK(completions("clrt scene.ray --mode \"\"") == "trace cast path\n");  // in --help's order
  CHECK(completions("clrt --integrator w") == "wavefront\n");
  CHECK(completions("clrt --frame") == "--frames --frame-range\n");
  CHECK(completions("clrt --spp \"\"") == "\n");  // a number: nothing to offer
  CHECK(completions("clrt --device \"\"") == "cpu gpu all\n");  // words, not file names
  CHECK(completions("clrt --device g") == "gpu\n");
}

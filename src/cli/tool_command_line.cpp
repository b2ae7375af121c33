#include "cli/tool_command_line.hpp"

#include <sstream>

#include "cli/unknown_words.hpp"
#include "version.hpp"

namespace clrt {

void identify_tool(CLI::App& app) {
  const std::string name = app.get_name();
  app.set_version_flag("--version", name == "clrt" ? std::string(clrt_version_string())
                                                   : name + ", from " + clrt_version_string());
  app.failure_message([name](const CLI::App*, const CLI::Error& error) {
    return name + ": error: " + error.what() + "\nRun '" + name + " --help' for usage.\n";
  });
}

std::optional<int> parse_tool_arguments(CLI::App& app, std::vector<std::string> args,
                                        bool print) {
  const auto report = [&](const CLI::ParseError& e) {
    std::ostringstream silent;
    return print ? app.exit(e) : app.exit(e, silent, silent);
  };
  try {
    app.parse(std::vector<std::string>(args.rbegin(), args.rend()));  // CLI11 takes them last first
  } catch (const CLI::ParseError& e) {
    if (e.get_exit_code() == 0) return report(e);
    const std::optional<std::string> culprit = unknown_word_message(app, args);
    if (culprit)
      report(CLI::ParseError(*culprit, e.get_exit_code()));
    else
      report(e);
    return 2;
  }
  return std::nullopt;
}

std::optional<int> parse_tool_arguments(CLI::App& app, int argc, char** argv) {
  return parse_tool_arguments(app, std::vector<std::string>(argv + 1, argv + argc));
}

}  // namespace clrt

#include "cli/tool_command_line.hpp"

#include <algorithm>
#include <sstream>

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
  try {
    std::reverse(args.begin(), args.end());  // CLI11 takes them last first
    app.parse(args);
  } catch (const CLI::ParseError& e) {
    std::ostringstream silent;
    const int status = print ? app.exit(e) : app.exit(e, silent, silent);
    return status == 0 ? 0 : 2;
  }
  return std::nullopt;
}

std::optional<int> parse_tool_arguments(CLI::App& app, int argc, char** argv) {
  return parse_tool_arguments(app, std::vector<std::string>(argv + 1, argv + argc));
}

}  // namespace clrt

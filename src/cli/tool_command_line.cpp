#include "cli/tool_command_line.hpp"

#include <sstream>

#include "cli/docs/doc_location.hpp"
#include "cli/unknown_words.hpp"
#include "version.hpp"

namespace clrt {
namespace {

// For words left over once every option and positional argument took theirs (CLI11's "The
// following argument was not expected"): which word, and what the program takes instead.
std::string extras_message(const CLI::App& app) {
  const std::vector<std::string> extra = app.remaining();
  std::string message = extra.size() == 1 ? "unexpected argument '" + extra.front() + "'"
                                          : "unexpected arguments";
  if (extra.size() > 1)
    for (const std::string& word : extra) message += " '" + word + "'";
  for (const CLI::Option* option : app.get_options()) {
    if (!option->get_positional() || option->get_expected_max() != 1 || option->count() != 1)
      continue;
    message += " (" + app.get_name() + " takes one " + option->get_name() +
               ", already given as '" + option->as<std::string>() + "')";
    break;
  }
  return message;
}

}  // namespace

void identify_tool(CLI::App& app, const ToolManual& manual) {
  const std::string name = app.get_name();
  add_cli_docs_option(app, manual);
  if (!manual.page.empty())
    app.footer("The whole manual: man " + name + ", and " + cli_docs::documentation_folder() + "/" +
               manual.page);
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
    // 0: --help, --version, --write-cli-docs; a RuntimeError has said what failed.
    if (e.get_exit_code() == 0 || dynamic_cast<const CLI::RuntimeError*>(&e)) return report(e);
    const std::optional<std::string> culprit = unknown_word_message(app, args);
    if (culprit)
      report(CLI::ParseError(*culprit, e.get_exit_code()));
    else if (dynamic_cast<const CLI::ExtrasError*>(&e))
      report(CLI::ParseError(extras_message(app), e.get_exit_code()));
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

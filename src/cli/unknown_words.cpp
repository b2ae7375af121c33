#include "cli/unknown_words.hpp"

#include <algorithm>
#include <cstdlib>

#include "text/nearest_name.hpp"

namespace clrt {
namespace {

// The program and the commands chosen on its command line: the options any of them defines
// are the ones the words may use.
std::vector<const CLI::App*> chosen_apps(const CLI::App& app) {
  std::vector<const CLI::App*> apps{&app};
  for (std::size_t i = 0; i < apps.size(); ++i)
    for (const CLI::App* command : apps[i]->get_subcommands()) apps.push_back(command);
  return apps;
}

// Every option's names as written on a command line: "--resolution", "-o".
std::vector<std::string> option_names(const std::vector<const CLI::App*>& apps) {
  std::vector<std::string> names;
  for (const CLI::App* app : apps)
    for (const CLI::Option* option : app->get_options()) {
      for (const std::string& name : option->get_lnames()) names.push_back("--" + name);
      for (const std::string& name : option->get_snames()) names.push_back("-" + name);
    }
  return names;
}

std::string without_dashes(const std::string& word) {
  return word.substr(std::min(word.find_first_not_of('-'), word.size()));
}

// Options are compared without their dashes, so that -outfile still finds --outfile.
std::string unknown(const std::string& kind, const std::string& word,
                    const std::vector<std::string>& names) {
  std::vector<std::string> bare;
  for (const std::string& name : names) bare.push_back(without_dashes(name));
  const std::optional<std::string> near = nearest_name(without_dashes(word), bare);
  std::string message = "unknown " + kind + " " + word;
  if (near) {
    const auto at = std::find(bare.begin(), bare.end(), *near) - bare.begin();
    message += " (did you mean " + names[static_cast<std::size_t>(at)] + "?)";
  }
  return message;
}

bool is_number(const std::string& word) {
  char* end = nullptr;
  std::strtod(word.c_str(), &end);
  return end != word.c_str() && *end == '\0';
}

// A word that CLI11 takes for an option (rather than a value, a file or "-" for standard
// output), as the option's name: "--outfile=x.png" -> "--outfile".
std::optional<std::string> option_word(const std::string& word) {
  if (word.size() < 2 || word[0] != '-' || is_number(word)) return std::nullopt;
  if (word[1] != '-') return word;
  return word.substr(0, word.find('='));
}

bool is_known(const std::string& option, const std::vector<std::string>& names) {
  // A short option may carry its value in the same word: -oimage.png.
  const std::string name = option[1] == '-' ? option : option.substr(0, 2);
  return std::find(names.begin(), names.end(), name) != names.end();
}

}  // namespace

std::optional<std::string> unknown_word_message(const CLI::App& app,
                                                const std::vector<std::string>& args) {
  const std::vector<const CLI::App*> apps = chosen_apps(app);
  const std::vector<std::string> names = option_names(apps);
  const bool wants_command = app.get_require_subcommand_min() > 0 && apps.size() == 1;
  std::optional<std::string> first_plain_word;
  for (const std::string& word : args) {
    if (word == "--") break;
    if (const std::optional<std::string> option = option_word(word)) {
      if (!is_known(*option, names)) return unknown("option", *option, names);
    } else if (!first_plain_word) {
      first_plain_word = word;
    }
  }
  if (!wants_command) return std::nullopt;
  std::vector<std::string> commands;
  for (const CLI::App* command : app.get_subcommands({})) commands.push_back(command->get_name());
  if (!first_plain_word) return "a command is required: " + CLI::detail::join(commands, ", ");
  return unknown("command", *first_plain_word, commands);
}

}  // namespace clrt

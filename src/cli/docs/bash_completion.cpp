#include "cli/docs/bash_completion.hpp"

#include <sstream>

#include "cli/docs/option_list.hpp"

namespace clrt::cli_docs {
namespace {

std::string joined(const std::vector<std::string>& words, const std::string& between) {
  std::string text;
  for (const std::string& word : words) text += (text.empty() ? "" : between) + word;
  return text;
}

// Free-text options whose usual values are words, not paths: --device takes a name or P:D too,
// but these words are what one types.
std::string usual_words(const OptionEntry& option) {
  for (const std::string& name : option.names)
    if (name == "--device") return "cpu gpu all";
  return "";
}

// Numbers cannot be completed; any other free text is most often a path.
bool takes_a_number(const std::string& value) {
  const std::string kind = value.substr(0, value.find(':'));
  return kind == "INT" || kind == "UINT" || kind == "FLOAT" || kind == "NUMBER";
}

// Completes the word at the cursor for one parser (the program's, or the command's it names):
// the value of the option before it, an option name, or a positional argument's file. Each line
// is indented by `pad`.
std::string completion_block(const CLI::App& app, const std::vector<std::string>& positional_extensions,
                             const std::string& pad) {
  std::vector<std::string> all_names, file_values, number_values;
  std::ostringstream choices;
  for (const OptionEntry& option : listed_options(app)) {
    all_names.insert(all_names.end(), option.names.begin(), option.names.end());
    if (option.value.empty()) continue;
    const std::string names = joined(option.names, "|");
    const std::string words =
        option.choices.empty() ? usual_words(option) : joined(option.choices, " ");
    if (!words.empty())
      choices << pad << "  " << names << ") COMPREPLY=($(compgen -W '" << words
              << "' -- \"$cur\")); return ;;\n";
    else if (takes_a_number(option.value))
      number_values.push_back(names);
    else
      file_values.push_back(names);
  }
  std::ostringstream out;
  out << pad << "case \"$prev\" in\n" << choices.str();
  if (!number_values.empty()) out << pad << "  " << joined(number_values, "|") << ") return ;;\n";
  if (!file_values.empty())
    out << pad << "  " << joined(file_values, "|")
        << ") COMPREPLY=($(compgen -f -- \"$cur\")); return ;;\n";
  out << pad << "esac\n"
      << pad << "if [[ \"$cur\" == -* ]]; then\n"
      << pad << "  COMPREPLY=($(compgen -W '" << joined(all_names, " ") << "' -- \"$cur\"))\n"
      << pad << "  return\n"
      << pad << "fi\n";
  if (positional_extensions.empty()) {
    out << pad << "COMPREPLY=($(compgen -f -- \"$cur\"))\n";
  } else {
    out << pad << "COMPREPLY=($(compgen -d -- \"$cur\")";
    for (const std::string& extension : positional_extensions)
      out << " $(compgen -f -X '!*." << extension << "' -- \"$cur\")";
    out << ")\n";
  }
  return out.str();
}

}  // namespace

std::string bash_completion(const CLI::App& app, const std::vector<std::string>& positional_extensions) {
  std::string function = "_" + app.get_name();
  for (char& c : function)
    if (c == '-') c = '_';
  std::ostringstream out;
  out << "# bash completion for " << app.get_name() << ", generated from its own parser.\n"
      << function << "() {\n"
      << "  local cur=\"${COMP_WORDS[COMP_CWORD]}\" prev=\"${COMP_WORDS[COMP_CWORD-1]}\"\n"
      << "  COMPREPLY=()\n";
  const std::vector<const CLI::App*> commands = app.get_subcommands({});
  if (commands.empty()) {
    out << completion_block(app, positional_extensions, "  ");
  } else {
    // The first command named before the cursor decides whose options and files come next.
    std::vector<std::string> names;
    for (const CLI::App* command : commands) names.push_back(command->get_name());
    out << "  local command=\"\" word\n"
        << "  for word in \"${COMP_WORDS[@]:1:COMP_CWORD-1}\"; do\n"
        << "    case \"$word\" in " << joined(names, "|") << ") command=\"$word\"; break ;; esac\n"
        << "  done\n"
        << "  case \"$command\" in\n";
    for (const CLI::App* command : commands)
      out << "    " << command->get_name() << ")\n"
          << completion_block(*command, {}, "      ") << "      ;;\n";
    std::vector<std::string> own_names;
    for (const OptionEntry& option : listed_options(app))
      own_names.insert(own_names.end(), option.names.begin(), option.names.end());
    out << "    *)\n"
        << "      if [[ \"$cur\" == -* ]]; then\n"
        << "        COMPREPLY=($(compgen -W '" << joined(own_names, " ") << "' -- \"$cur\"))\n"
        << "      else\n"
        << "        COMPREPLY=($(compgen -W '" << joined(names, " ") << "' -- \"$cur\"))\n"
        << "      fi\n"
        << "      ;;\n"
        << "  esac\n";
  }
  out << "}\n"
      << "complete -o filenames -F " << function << " " << app.get_name() << "\n";
  return out.str();
}

}  // namespace clrt::cli_docs

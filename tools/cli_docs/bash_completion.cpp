#include "bash_completion.hpp"

#include <sstream>

#include "option_list.hpp"

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

}  // namespace

std::string bash_completion(const CLI::App& app, const std::vector<std::string>& positional_extensions) {
  std::string function = "_" + app.get_name();
  for (char& c : function)
    if (c == '-') c = '_';
  std::vector<std::string> all_names, file_values, number_values;
  std::ostringstream choices;
  for (const OptionEntry& option : listed_options(app)) {
    all_names.insert(all_names.end(), option.names.begin(), option.names.end());
    if (option.value.empty()) continue;
    const std::string names = joined(option.names, "|");
    const std::string words =
        option.choices.empty() ? usual_words(option) : joined(option.choices, " ");
    if (!words.empty())
      choices << "    " << names << ") COMPREPLY=($(compgen -W '" << words
              << "' -- \"$cur\")); return ;;\n";
    else if (takes_a_number(option.value))
      number_values.push_back(names);
    else
      file_values.push_back(names);
  }
  std::ostringstream out;
  out << "# bash completion for " << app.get_name() << ", generated from its own parser.\n"
      << function << "() {\n"
      << "  local cur=\"${COMP_WORDS[COMP_CWORD]}\" prev=\"${COMP_WORDS[COMP_CWORD-1]}\"\n"
      << "  COMPREPLY=()\n"
      << "  case \"$prev\" in\n"
      << choices.str();
  if (!number_values.empty()) out << "    " << joined(number_values, "|") << ") return ;;\n";
  if (!file_values.empty())
    out << "    " << joined(file_values, "|") << ") COMPREPLY=($(compgen -f -- \"$cur\")); return ;;\n";
  out << "  esac\n"
      << "  if [[ \"$cur\" == -* ]]; then\n"
      << "    COMPREPLY=($(compgen -W '" << joined(all_names, " ") << "' -- \"$cur\"))\n"
      << "    return\n"
      << "  fi\n"
      << "  COMPREPLY=($(compgen -d -- \"$cur\")";
  for (const std::string& extension : positional_extensions)
    out << " $(compgen -f -X '!*." << extension << "' -- \"$cur\")";
  out << ")\n"
      << "}\n"
      << "complete -o filenames -F " << function << " " << app.get_name() << "\n";
  return out.str();
}

}  // namespace clrt::cli_docs

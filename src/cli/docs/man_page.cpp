#include "cli/docs/man_page.hpp"

#include <algorithm>

#include <sstream>

#include "cli/docs/option_list.hpp"

namespace clrt::cli_docs {
namespace {

// Text as roff prints it literally: backslashes and hyphens escaped, and no line starting with
// a control character.
std::string roff(const std::string& text) {
  std::string out;
  for (const char c : text) {
    if (c == '\\') out += "\\e";
    else if (c == '-') out += "\\-";
    else out += c;
  }
  if (!out.empty() && (out[0] == '.' || out[0] == '\'')) out.insert(0, "\\&");
  return out;
}

std::string upper(std::string text) {
  for (char& c : text) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  return text;
}

// ".TP" then the names in bold and the value in italics: "-o, --outfile TEXT".
void write_option(std::ostream& out, const OptionEntry& option) {
  out << ".TP\n";
  for (std::size_t i = 0; i < option.names.size(); ++i)
    out << (i ? ", " : "") << "\\fB" << roff(option.names[i]) << "\\fR";
  if (!option.value.empty()) out << " \\fI" << roff(option.value) << "\\fR";
  out << "\n" << roff(option.description) << "\n";
}

// The positional arguments' names as the synopsis shows them: " \fISCENE\fR".
std::string positional_names(const CLI::App& app) {
  std::string names;
  for (const CLI::Option* positional : app.get_options())
    if (positional->get_positional()) names += " \\fI" + roff(upper(positional->get_name())) + "\\fR";
  return names;
}

void write_positionals(std::ostream& out, const CLI::App& app) {
  for (const CLI::Option* positional : app.get_options())
    if (positional->get_positional())
      out << ".TP\n\\fI" << roff(upper(positional->get_name())) << "\\fR\n"
          << roff(positional->get_description()) << "\n";
}

// Each group once, in the order it first appears, as --help lists them: options added to a group
// later (--preview after the animation's) join it there. `heading` is the macro of a group's
// title (".SS"), or empty where the groups are not named (a command's options).
void write_option_groups(std::ostream& out, const CLI::App& app, const std::string& heading) {
  const std::vector<OptionEntry> options = listed_options(app);
  std::vector<std::string> groups;
  for (const OptionEntry& option : options)
    if (std::find(groups.begin(), groups.end(), option.group) == groups.end())
      groups.push_back(option.group);
  for (const std::string& group : groups) {
    if (!heading.empty()) out << heading << " " << roff(group) << "\n";
    for (const OptionEntry& option : options)
      if (option.group == group) write_option(out, option);
  }
}

// A section of tagged paragraphs, each term in bold (a status or a command line, as it is typed).
void write_list(std::ostream& out, const std::string& title, const std::vector<ManualLine>& lines) {
  if (lines.empty()) return;
  out << ".SH " << title << "\n";
  for (const ManualLine& line : lines)
    out << ".TP\n\\fB" << roff(line.term) << "\\fR\n" << roff(line.text) << "\n";
}

}  // namespace

std::string man_page(const CLI::App& app, const std::string& version, const ManPageSections& sections) {
  std::ostringstream out;
  const std::string name = app.get_name();
  const std::vector<const CLI::App*> commands = app.get_subcommands({});
  out << ".TH " << roff(upper(name)) << " 1 \"\" \"" << roff(version) << "\" \"User Commands\"\n";
  const std::string description = app.get_description();
  const std::size_t colon = description.find(": ");
  out << ".SH NAME\n"
      << roff(name) << " \\- "
      << roff(colon == std::string::npos ? description : description.substr(colon + 2)) << "\n";
  out << ".SH SYNOPSIS\n";
  if (commands.empty()) out << ".B " << roff(name) << "\n[\\fIOPTIONS\\fR]" << positional_names(app) << "\n";
  for (std::size_t i = 0; i < commands.size(); ++i)
    out << (i ? ".br\n" : "") << ".B " << roff(name) << " " << roff(commands[i]->get_name())
        << "\n[\\fIOPTIONS\\fR]" << positional_names(*commands[i]) << "\n";
  if (commands.empty()) {
    out << ".SH DESCRIPTION\n";
    write_positionals(out, app);
  }
  out << ".SH OPTIONS\n";
  write_option_groups(out, app, ".SS");
  if (!commands.empty()) {
    out << ".SH COMMANDS\n";
    for (const CLI::App* command : commands) {
      out << ".SS " << roff(command->get_name()) << "\n" << roff(command->get_description()) << "\n";
      write_positionals(out, *command);
      write_option_groups(out, *command, "");
    }
  }
  write_list(out, "EXIT STATUS", sections.exit_status);
  write_list(out, "EXAMPLES", sections.examples);
  out << ".SH SEE ALSO\n" << roff(sections.see_also) << "\n";
  return out.str();
}

}  // namespace clrt::cli_docs

#include "man_page.hpp"

#include <algorithm>

#include <sstream>

#include "option_list.hpp"

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

}  // namespace

std::string man_page(const CLI::App& app, const std::string& version, const std::string& see_also) {
  std::ostringstream out;
  const std::string name = app.get_name();
  out << ".TH " << upper(name) << " 1 \"\" \"" << roff(version) << "\" \"User Commands\"\n";
  const std::string description = app.get_description();
  const std::size_t colon = description.find(": ");
  out << ".SH NAME\n"
      << roff(name) << " \\- "
      << roff(colon == std::string::npos ? description : description.substr(colon + 2)) << "\n";
  out << ".SH SYNOPSIS\n.B " << roff(name) << "\n[\\fIOPTIONS\\fR]";
  for (const CLI::Option* positional : app.get_options())
    if (positional->get_positional()) out << " \\fI" << roff(upper(positional->get_name())) << "\\fR";
  out << "\n.SH DESCRIPTION\n";
  for (const CLI::Option* positional : app.get_options())
    if (positional->get_positional())
      out << ".TP\n\\fI" << roff(upper(positional->get_name())) << "\\fR\n"
          << roff(positional->get_description()) << "\n";
  out << ".SH OPTIONS\n";
  // Each group once, in the order it first appears, as --help lists them: options added to a
  // group later (--preview after the animation's) join it there.
  const std::vector<OptionEntry> options = listed_options(app);
  std::vector<std::string> groups;
  for (const OptionEntry& option : options)
    if (std::find(groups.begin(), groups.end(), option.group) == groups.end())
      groups.push_back(option.group);
  for (const std::string& group : groups) {
    out << ".SS " << roff(group) << "\n";
    for (const OptionEntry& option : options)
      if (option.group == group) write_option(out, option);
  }
  out << ".SH SEE ALSO\n" << roff(see_also) << "\n";
  return out.str();
}

}  // namespace clrt::cli_docs

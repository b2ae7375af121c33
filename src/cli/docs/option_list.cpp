#include "cli/docs/option_list.hpp"

namespace clrt::cli_docs {
namespace {

// CLI::IsMember describes itself as "{a,b,c}"; that is the only fixed set of words CLI11 names.
std::vector<std::string> choices_of(const CLI::Option& option) {
  const std::string type = option.get_type_name();
  const std::size_t open = type.find('{'), close = type.find('}', open);
  if (open == std::string::npos || close == std::string::npos) return {};
  return CLI::detail::split(type.substr(open + 1, close - open - 1), ',');
}

}  // namespace

std::vector<OptionEntry> listed_options(const CLI::App& app) {
  std::vector<OptionEntry> entries;
  for (const CLI::Option* option : app.get_options()) {
    if (option->get_positional() || option->get_group().empty()) continue;
    OptionEntry entry;
    for (const std::string& name : option->get_snames()) entry.names.push_back("-" + name);
    for (const std::string& name : option->get_lnames()) entry.names.push_back("--" + name);
    if (option->get_type_size_max() > 0) entry.value = option->get_type_name();
    entry.choices = choices_of(*option);
    entry.description = option->get_description();
    entry.group = option->get_group();
    entries.push_back(std::move(entry));
  }
  return entries;
}

}  // namespace clrt::cli_docs

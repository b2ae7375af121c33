#include "render/integrator.hpp"

#include <algorithm>
#include <cctype>
#include <stdexcept>

namespace clrt {

// Each defined in its integrator's own file.
const IntegratorEntry& wavefront_integrator();
const IntegratorEntry& megakernel_integrator();

const std::vector<IntegratorEntry>& integrator_table() {
  static const std::vector<IntegratorEntry> table{wavefront_integrator(), megakernel_integrator()};
  return table;
}

const IntegratorEntry& integrator_entry(const std::string& name) {
  for (const IntegratorEntry& entry : integrator_table())
    if (name == entry.name) return entry;
  throw std::logic_error("no integrator '" + name + "' in integrator_table()");
}

std::string integrator_program_options(DeviceClass device_class) {
  std::string options;
  for (const IntegratorEntry& entry : integrator_table()) {
    const std::string own = entry.program_options(device_class);
    if (!own.empty()) options += (options.empty() ? "" : " ") + own;
  }
  return options;
}

std::optional<std::string> parse_integrator(const std::string& name) {
  std::string lower = name;
  std::transform(lower.begin(), lower.end(), lower.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  for (const IntegratorEntry& entry : integrator_table())
    if (lower == entry.name) return lower;
  return std::nullopt;
}

std::vector<std::string> integrator_names() {
  std::vector<std::string> names;
  for (const IntegratorEntry& entry : integrator_table()) names.emplace_back(entry.name);
  return names;
}

std::string integrator_summaries() {
  std::string text;
  for (const IntegratorEntry& entry : integrator_table())
    text += std::string(text.empty() ? "" : "; ") + entry.name + ": " + entry.summary;
  return text;
}

}  // namespace clrt

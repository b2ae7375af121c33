#include "cli/whole_number.hpp"

#include <cstdlib>

namespace clrt {

std::optional<std::int64_t> parse_whole_number(const std::string& text) {
  const std::size_t digits_from = !text.empty() && (text[0] == '-' || text[0] == '+') ? 1 : 0;
  if (text.size() == digits_from) return std::nullopt;
  for (std::size_t i = digits_from; i < text.size(); ++i)
    if (text[i] < '0' || text[i] > '9') return std::nullopt;
  return static_cast<std::int64_t>(std::strtoll(text.c_str(), nullptr, 10));
}

CLI::Validator whole_number(std::int64_t min, std::int64_t max) {
  const std::string range = std::to_string(min) + " to " + std::to_string(max);
  return CLI::Validator(
      [min, max, range](std::string& text) {
        const std::optional<std::int64_t> value = parse_whole_number(text);
        if (!value) return text + " is not a whole number";
        if (*value < min || *value > max) return text + " is not in the range " + range;
        text = std::to_string(*value);
        return std::string();
      },
      range);
}

}  // namespace clrt

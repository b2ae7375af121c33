#include "cli/whole_number.hpp"

#include <cstdlib>
#include <limits>

namespace clrt {

std::optional<std::int64_t> parse_whole_number(const std::string& text) {
  const std::size_t digits_from = !text.empty() && (text[0] == '-' || text[0] == '+') ? 1 : 0;
  if (text.size() == digits_from) return std::nullopt;
  for (std::size_t i = digits_from; i < text.size(); ++i)
    if (text[i] < '0' || text[i] > '9') return std::nullopt;
  return static_cast<std::int64_t>(std::strtoll(text.c_str(), nullptr, 10));
}

namespace {

// `not_number` and `outside` follow the word the user gave.
CLI::Validator whole_number_worded(std::int64_t min, std::int64_t max, std::string not_number,
                                   std::string outside) {
  return CLI::Validator(
      [=](std::string& text) {
        const std::optional<std::int64_t> value = parse_whole_number(text);
        if (!value) return text + not_number;
        if (*value < min || *value > max) return text + outside;
        text = std::to_string(*value);
        return std::string();
      },
      std::to_string(min) + " to " + std::to_string(max));
}

}  // namespace

CLI::Validator whole_number(std::int64_t min, std::int64_t max) {
  return whole_number_worded(min, max, " is not a whole number",
                             " is not in the range " + std::to_string(min) + " to " +
                                 std::to_string(max));
}

CLI::Validator seed_number() {
  const std::string accepted = " is not a seed: seeds are the whole numbers 0 to " +
                               std::to_string(std::numeric_limits<std::uint32_t>::max());
  return whole_number_worded(0, std::numeric_limits<std::uint32_t>::max(), accepted, accepted);
}

}  // namespace clrt

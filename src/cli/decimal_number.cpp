#include "cli/decimal_number.hpp"

#include <cmath>
#include <cstdlib>
#include <optional>
#include <sstream>

namespace clrt {
namespace {

constexpr double kNoBound = std::numeric_limits<double>::max();

// `text` as a finite decimal number, or nothing: no hexadecimal, inf or nan, which strtod alone
// would take.
std::optional<double> parse_decimal(const std::string& text) {
  if (text.empty() || text.find_first_of("xXiInN") != std::string::npos) return std::nullopt;
  char* end = nullptr;
  const double value = std::strtod(text.c_str(), &end);
  if (end != text.c_str() + text.size() || !std::isfinite(value)) return std::nullopt;
  return value;
}

std::string shortest(double value) {
  std::ostringstream text;
  text << value;
  return text.str();
}

// What a number out of the bounds is told, as "VALUE" followed by it.
std::string range_message(double min, double max, bool above_min) {
  if (above_min) return " is not above " + shortest(min);
  if (max == kNoBound) return " is less than " + shortest(min);
  if (min == -kNoBound) return " is more than " + shortest(max);
  return " is not in the range " + shortest(min) + " to " + shortest(max);
}

CLI::Validator bounded_decimal(double min, double max, bool above_min) {
  const std::string outside = range_message(min, max, above_min);
  return CLI::Validator(
      [=](std::string& text) {
        const std::optional<double> value = parse_decimal(text);
        if (!value) return text + " is not a number";
        if (*value < min || *value > max || (above_min && *value == min)) return text + outside;
        return std::string();
      },
      "");
}

}  // namespace

CLI::Validator decimal_number(double min, double max) { return bounded_decimal(min, max, false); }

CLI::Validator positive_decimal_number() { return bounded_decimal(0, kNoBound, true); }

}  // namespace clrt

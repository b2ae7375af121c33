#include "scene/number.hpp"

#include <cctype>
#include <charconv>
#include <cstddef>
#include <cmath>
#include <system_error>

#include "scene/limits.hpp"

namespace clrt {
namespace {

std::size_t skip_digits(std::string_view s, std::size_t i) {
  while (i < s.size() && std::isdigit(static_cast<unsigned char>(s[i]))) ++i;
  return i;
}

std::size_t skip_sign(std::string_view s, std::size_t i) {
  return i < s.size() && (s[i] == '+' || s[i] == '-') ? i + 1 : i;
}

// [+-] (digits [. [digits]] | . digits) [(e|E) [+-] digits]
bool is_decimal_float(std::string_view s) {
  std::size_t i = skip_sign(s, 0);
  const std::size_t int_end = skip_digits(s, i);
  std::size_t digits = int_end - i;
  i = int_end;
  if (i < s.size() && s[i] == '.') {
    const std::size_t frac_end = skip_digits(s, i + 1);
    digits += frac_end - (i + 1);
    i = frac_end;
  }
  if (digits == 0) return false;
  if (i < s.size() && (s[i] == 'e' || s[i] == 'E')) {
    const std::size_t exp_start = skip_sign(s, i + 1);
    i = skip_digits(s, exp_start);
    if (i == exp_start) return false;
  }
  return i == s.size();
}

bool equals_ignoring_case(std::string_view a, std::string_view b) {
  if (a.size() != b.size()) return false;
  for (std::size_t i = 0; i < a.size(); ++i)
    if (std::tolower(static_cast<unsigned char>(a[i])) != b[i]) return false;
  return true;
}

bool spells_non_finite(std::string_view s) {
  const std::string_view body = s.substr(skip_sign(s, 0));
  return equals_ignoring_case(body, "nan") || equals_ignoring_case(body, "inf") ||
         equals_ignoring_case(body, "infinity");
}

}  // namespace

ParsedNumber parse_number(std::string_view word) {
  if (spells_non_finite(word)) return {0, NumberProblem::NotFinite};
  if (!is_decimal_float(word)) return {0, NumberProblem::NotANumber};
  // std::from_chars takes no leading '+'.
  const std::string_view digits = word.front() == '+' ? word.substr(1) : word;
  ParsedNumber parsed;
  const auto result = std::from_chars(digits.data(), digits.data() + digits.size(), parsed.value);
  if (result.ec == std::errc::result_out_of_range) return {0, NumberProblem::OutOfRange};
  if (std::fabs(parsed.value) > limits::kMaxNumber) return {0, NumberProblem::TooLarge};
  return parsed;
}

}  // namespace clrt

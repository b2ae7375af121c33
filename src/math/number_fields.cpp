#include "math/number_fields.hpp"

namespace clrt {
namespace {

bool is_digit(char c) { return c >= '0' && c <= '9'; }

char lower(char c) { return c >= 'A' && c <= 'Z' ? static_cast<char>(c - 'A' + 'a') : c; }

}  // namespace

std::optional<std::vector<std::uint64_t>> read_number_fields(std::string_view text, const NumberForm& form) {
  std::vector<std::uint64_t> numbers;
  std::size_t at = 0;
  for (const char p : form.pattern) {
    if (p != '#') {
      if (at == text.size() || (form.any_case ? lower(text[at]) != lower(p) : text[at] != p)) return std::nullopt;
      ++at;
      continue;
    }
    const std::size_t first = at;
    std::uint64_t value = 0;
    // At most 19 digits, so that the value cannot overflow.
    while (at < text.size() && is_digit(text[at]) && at - first < static_cast<std::size_t>(form.max_digits) &&
           at - first < 19)
      value = value * 10 + static_cast<std::uint64_t>(text[at++] - '0');
    if (at == first || (at < text.size() && is_digit(text[at]))) return std::nullopt;
    if (form.no_leading_zeros && text[first] == '0' && at - first > 1) return std::nullopt;
    numbers.push_back(value);
  }
  if (at != text.size()) return std::nullopt;
  return numbers;
}

}  // namespace clrt

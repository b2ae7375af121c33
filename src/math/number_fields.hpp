// Whole numbers in a fixed spelling, such as "640x480", "1:24" or "0,0 32x32 of 64x64": read by
// hand rather than with <regex>, whose templates cost several seconds of every first build.
#pragma once

#include <cstdint>
#include <optional>
#include <string_view>
#include <vector>

namespace clrt {

struct NumberForm {
  std::string_view pattern;  // each '#' is a number; every other character stands for itself
  int max_digits = 10;       // digits a number may have (at least 1)
  bool no_leading_zeros = false;  // "0" but not "07": one spelling for each number
  bool any_case = false;     // letters of the pattern match either case ("1280X720")
};

// The numbers of `text` when all of it is spelled as `form` says; nothing otherwise.
std::optional<std::vector<std::uint64_t>> read_number_fields(std::string_view text, const NumberForm& form);

}  // namespace clrt

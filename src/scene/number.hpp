// Strict parsing of the decimal numbers a .ray file may contain.
#pragma once

#include <string_view>

namespace clrt {

enum class NumberProblem {
  None,
  NotANumber,  // not entirely a decimal float such as `.5`, `-2`, `1e-3`
  NotFinite,   // spelled NaN or Inf
  OutOfRange,  // a decimal float too large (or too small) for a double, like 1e999
  TooLarge,    // a double beyond +-limits::kMaxNumber, like 1e13
};

struct ParsedNumber {
  double value = 0;
  NumberProblem problem = NumberProblem::None;
};

// Locale-independent: `.` is always the decimal point. Hexadecimal floats, leading or trailing
// spaces, and anything after the number are rejected. Every scene format's loader parses its
// numbers here, so all of them share the limit on their size.
ParsedNumber parse_number(std::string_view word);

}  // namespace clrt

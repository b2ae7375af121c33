// The check of every option that takes a decimal number (a fraction, an angle, a threshold), in
// every clrt tool, worded as whole_number() words a count's: CLI11 alone would say "Could not
// convert: --orbit = abc".
#pragma once

#include <CLI/CLI.hpp>

#include <limits>

namespace clrt {

// Accepts finite decimal numbers from `min` to `max` (a sign, digits with an optional point, an
// optional exponent: what strtod reads, less hexadecimal, inf and nan). Its messages are
// "abc is not a number" and "-1 is not in the range 0 to 1", or "-1 is less than 0" without an
// upper bound (CLI11 puts the option's name before them). Give it to ->check().
CLI::Validator decimal_number(double min = std::numeric_limits<double>::lowest(),
                              double max = std::numeric_limits<double>::max());

// Accepts finite numbers above 0 ("0 is not above 0"): a scale or a factor.
CLI::Validator positive_decimal_number();

}  // namespace clrt

// The check of every option that takes a count, in every clrt tool: a word that is no number
// is told so, rather than being "not in range".
#pragma once

#include <CLI/CLI.hpp>

#include <cstdint>
#include <optional>
#include <string>

namespace clrt {

// `text` as a whole number in decimal (an optional sign, then digits only; beyond 64 bits it
// saturates), or nothing.
std::optional<std::int64_t> parse_whole_number(const std::string& text);

// Accepts whole numbers from `min` to `max`; its messages are "abc is not a whole number" and
// "0 is not in the range 1 to 65536" (CLI11 puts the option's name before them). Give it to
// ->transform(), not ->check(): it writes the number back in plain decimal, since CLI11 itself
// would read 010 as octal 8 and 0x10 as 16.
CLI::Validator whole_number(std::int64_t min, std::int64_t max);

// A seed of the random numbers: 0 to 2^32 - 1, whatever the word's fault, said as
// "-1 is not a seed: seeds are the whole numbers 0 to 4294967295".
CLI::Validator seed_number();

}  // namespace clrt

#include "scene/command_args.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>

#include "scene/limits.hpp"
#include "scene/number.hpp"

namespace clrt {
namespace {

// "3", "0 or 4", "9, 10 or 11": the accepted argument counts, for messages.
std::string list_counts(std::initializer_list<std::size_t> counts) {
  std::string text;
  std::size_t i = 0;
  for (std::size_t n : counts) {
    if (i > 0) text += i + 1 == counts.size() ? " or " : ", ";
    text += std::to_string(n);
    ++i;
  }
  return text;
}

}  // namespace

std::string lower_case(std::string s) {
  for (char& c : s) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return s;
}

bool looks_numeric(const Word& word) {
  return !word.quoted && parse_number(word.text).problem != NumberProblem::NotANumber;
}

CommandArgs::CommandArgs(const std::string& file, const Line& line)
    : file_(file), line_(line), name_(lower_case(line.words.front().text)) {}

void CommandArgs::require_count(std::initializer_list<std::size_t> allowed, std::size_t first,
                                const std::string& subject) const {
  const std::size_t found = count() - first;
  if (std::find(allowed.begin(), allowed.end(), found) != allowed.end()) return;
  const std::string message =
      "wrong number of arguments: " + subject + " takes " + list_counts(allowed) +
      (allowed.size() == 1 && *allowed.begin() == 1 ? " argument" : " arguments") +
      (first > 0 ? " after '" + excerpt(word(first - 1).text) + "'" : "") + ", found " +
      std::to_string(found);
  const std::size_t most = *std::max_element(allowed.begin(), allowed.end());
  if (found > most) throw error_at(first + most, message);
  throw error_past_end(message);
}

double CommandArgs::number(std::size_t i) const {
  const Word& w = word(i);
  const ParsedNumber parsed =
      w.quoted ? ParsedNumber{0, NumberProblem::NotANumber} : parse_number(w.text);
  switch (parsed.problem) {
    case NumberProblem::None:
      return parsed.value;
    case NumberProblem::NotANumber:
      throw error_at(i, "expected a number, found '" + excerpt(w.text) + "'");
    case NumberProblem::NotFinite:
      throw error_at(i, "'" + w.text + "' is not a finite number");
    case NumberProblem::OutOfRange:
      throw error_at(i, "'" + excerpt(w.text) + "' is out of the range of a double");
    case NumberProblem::TooLarge:
      break;
  }
  throw error_at(i, "'" + excerpt(w.text) + "' is too large: numbers in a scene lie within -" +
                        short_number(limits::kMaxNumber) + " and " +
                        short_number(limits::kMaxNumber));
}

Vec3 CommandArgs::vec3(std::size_t first) const {
  return {number(first), number(first + 1), number(first + 2)};
}

Vec3 CommandArgs::nonzero_vec3(std::size_t first, const std::string& what) const {
  const Vec3 v = vec3(first);
  if (v == Vec3{0, 0, 0}) throw error_at(first, what + " must not be a zero-length vector");
  return v;
}

int CommandArgs::whole_number(std::size_t i, int min, int max, const std::string& what) const {
  const double value = number(i);
  if (value != std::floor(value) || value < min || value > max)
    throw error_at(i, what + " must be a whole number from " + std::to_string(min) + " to " +
                          std::to_string(max) + ", found " + excerpt(word(i).text));
  return static_cast<int>(value);
}

double CommandArgs::number_in(std::size_t i, double lo, double hi, const std::string& what) const {
  const double value = number(i);
  if (value < lo || value > hi)
    throw error_at(i, what + " must be in [" + short_number(lo) + ", " + short_number(hi) +
                          "], found " + excerpt(word(i).text));
  return value;
}

SourceLocation CommandArgs::command_location() const {
  return {file_, line_.number, line_.words.front().column};
}

SceneError CommandArgs::error_at(std::size_t i, const std::string& message) const {
  return SceneError({file_, word(i).line, word(i).column}, message);
}

SceneError CommandArgs::error_past_end(const std::string& message) const {
  const Word& last = line_.words.back();
  return SceneError({file_, last.line, last.end_column}, message);
}

}  // namespace clrt

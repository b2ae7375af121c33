#include "frame_pattern.hpp"

#include <optional>
#include <string_view>

#include "command_line.hpp"

namespace clrt::img {
namespace {

// The widest padding accepted: more digits than any frame count needs is surely a mistake.
constexpr std::size_t kMaxDigits = 10;

[[noreturn]] void refuse(const std::string& pattern, const std::string& why) {
  throw UsageError(pattern + ": " + why +
                   "; a frame pattern takes one %d or %0Nd (e.g. %04d) for the frame number, "
                   "and %% for a % sign");
}

// The digits a conversion pads to: "%d" 0, "%04d" 4; nothing for any other conversion.
std::optional<std::size_t> padding(const std::string& spec) {
  if (spec == "%d") return 0;
  if (spec.size() < 4 || spec.size() > 5 || spec[1] != '0' || spec.back() != 'd')
    return std::nullopt;
  const std::string width = spec.substr(2, spec.size() - 3);
  if (width.find_first_not_of("0123456789") != std::string::npos) return std::nullopt;
  const std::size_t digits = std::stoul(width);
  if (digits > kMaxDigits) return std::nullopt;
  return digits;
}

}  // namespace

bool is_frame_pattern(const std::string& name) { return name.find('%') != std::string::npos; }

std::string frame_file_name(const std::string& pattern, int frame) {
  std::string name;
  int numbers = 0;
  for (std::size_t i = 0; i < pattern.size(); ++i) {
    if (pattern[i] != '%') {
      name += pattern[i];
    } else if (i + 1 < pattern.size() && pattern[i + 1] == '%') {
      name += '%';
      ++i;
    } else {
      // A printf conversion: flags and width, then its letter.
      std::size_t end = i + 1;
      while (end < pattern.size() && std::string_view("0123456789-+ #.").find(pattern[end]) !=
                                         std::string_view::npos)
        ++end;
      const std::string spec = pattern.substr(i, end + 1 - i);
      const std::optional<std::size_t> digits = padding(spec);
      if (!digits) refuse(pattern, spec + " is not a frame number");
      std::string number = std::to_string(frame);
      if (number.size() < *digits) number.insert(0, *digits - number.size(), '0');
      name += number;
      ++numbers;
      i = end;
    }
  }
  if (numbers != 1)
    refuse(pattern, numbers == 0 ? "it has no frame number" : "it has more than one frame number");
  return name;
}

}  // namespace clrt::img

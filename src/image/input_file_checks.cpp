#include "image/input_file_checks.hpp"

#include <fcntl.h>

namespace clrt {

// O_NONBLOCK changes nothing for a regular file, the only kind that is then read.
int open_input_at_once(const std::string& path) {
  return ::open(path.c_str(), O_RDONLY | O_CLOEXEC | O_NONBLOCK);
}

void check_input_status(const struct stat& info, std::uint64_t max_bytes) {
  if (S_ISDIR(info.st_mode)) throw InputFileError("it is a folder");
  if (!S_ISREG(info.st_mode)) throw InputFileError("it is not a regular file");
  if (static_cast<std::uint64_t>(info.st_size) > max_bytes)
    throw InputFileError("it is " + std::to_string(info.st_size) +
                         " bytes, more than the limit of " + size_limit_text(max_bytes));
}

std::string size_limit_text(std::uint64_t max_bytes) {
  return std::to_string(max_bytes >> 20) + " MiB";
}

std::string_view without_byte_order_mark(std::string_view text) {
  constexpr std::string_view kMark = "\xEF\xBB\xBF";
  return text.substr(0, kMark.size()) == kMark ? text.substr(kMark.size()) : text;
}

}  // namespace clrt

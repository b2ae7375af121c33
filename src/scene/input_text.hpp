// Reading a scene or mesh file whole, refusing what is not a file of text of a bounded size.
#pragma once

#include <cstdint>
#include <stdexcept>
#include <string>

namespace clrt {

// Why a file could not be read; what() is the reason alone (no path), for the caller to place.
class InputFileError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// Throws InputFileError unless `path` is a regular file (not a folder, device such as /dev/zero,
// or pipe) of at most `max_bytes`. Checks the name only: read_input_text() checks again while
// reading, since the file can change in between.
void check_input_file(const std::string& path, std::uint64_t max_bytes);

// The whole file, read only if check_input_file() passes for the open file, and never more than
// `max_bytes` even if the file grows while it is read.
std::string read_input_text(const std::string& path, std::uint64_t max_bytes);

}  // namespace clrt

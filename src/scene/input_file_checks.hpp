// What the loaders accept as an input file: a regular file of a bounded size.
#pragma once

#include <sys/stat.h>

#include <cstdint>
#include <stdexcept>
#include <string>
#include <string_view>

namespace clrt {

// Why a file could not be read; what() is the reason alone (no path), for the caller to place.
class InputFileError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// A file whose size or modification time changed while it was read (someone wrote it meanwhile).
class FileChangedError : public InputFileError {
 public:
  FileChangedError() : InputFileError("changed while being read") {}
};

// Throws InputFileError unless `info` describes a regular file (not a folder, a device such as
// /dev/zero, or a pipe) of at most `max_bytes`.
void check_input_status(const struct stat& info, std::uint64_t max_bytes);

// A file size limit as every message states it: "256 MiB".
std::string size_limit_text(std::uint64_t max_bytes);

// `text` without the UTF-8 byte order mark that some editors write at a file's start, which
// would otherwise be three invisible bytes in front of the first word.
std::string_view without_byte_order_mark(std::string_view text);

}  // namespace clrt

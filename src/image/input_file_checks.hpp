// What every reader of clrt accepts as an input file (scenes, meshes, textures, and the images the
// tools read): a regular file of a bounded size, refused at once when it is anything else.
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

// open(path, O_RDONLY) that never waits: a FIFO's open() would otherwise block until a writer
// came, before check_input_status() could refuse it. -1 and errno as open() on failure.
int open_input_at_once(const std::string& path);

// Throws InputFileError unless `info` describes a regular file (not a folder, a device such as
// /dev/zero, or a pipe) of at most `max_bytes`.
void check_input_status(const struct stat& info, std::uint64_t max_bytes);

// A file size limit as every message states it: "256 MiB".
std::string size_limit_text(std::uint64_t max_bytes);

// `text` without the UTF-8 byte order mark that some editors write at a file's start, which
// would otherwise be three invisible bytes in front of the first word.
std::string_view without_byte_order_mark(std::string_view text);

}  // namespace clrt

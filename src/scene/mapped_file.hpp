// A regular file mapped read-only into memory: its bytes are read in place, never copied.
#pragma once

#include <cstddef>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <string_view>

namespace clrt {

// A file that cannot be mapped; what() is "cannot be read (REASON)": the caller names the file.
class FileReadError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

class MappedFile {
 public:
  // Throws FileReadError for a file that cannot be opened, is not a regular file (a folder,
  // /dev/zero, a pipe), or is larger than `max_bytes`.
  MappedFile(const std::string& path, std::uint64_t max_bytes);
  ~MappedFile();
  MappedFile(const MappedFile&) = delete;
  MappedFile& operator=(const MappedFile&) = delete;

  std::string_view text() const { return {data_, size_}; }

 private:
  const char* data_ = nullptr;
  std::size_t size_ = 0;
};

}  // namespace clrt

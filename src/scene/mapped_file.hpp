// A regular file mapped read-only into memory: its bytes are read in place, never copied.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

#include "scene/file_source.hpp"

namespace clrt {

class MappedFile final : public FileBytes {
 public:
  // Throws InputFileError for a file that cannot be opened, is not a regular file (a folder,
  // /dev/zero, a pipe), or is larger than `max_bytes`.
  MappedFile(const std::string& path, std::uint64_t max_bytes);
  ~MappedFile() override;
  MappedFile(const MappedFile&) = delete;
  MappedFile& operator=(const MappedFile&) = delete;

  std::string_view text() const override { return {data_, size_}; }

 private:
  const char* data_ = nullptr;
  std::size_t size_ = 0;
};

}  // namespace clrt

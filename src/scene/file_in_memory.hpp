// A regular file read whole into memory with read(2), and checked to be the same file, unchanged,
// at the end of the read. (It was mapped once; a file that shrank under the mapping killed clrt
// with SIGBUS at the first page past its new end, in whichever thread touched it.)
#pragma once

#include <cstddef>
#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <string_view>

#include "scene/file_source.hpp"

namespace clrt {

class FileInMemory final : public FileBytes {
 public:
  // Throws InputFileError for a file that cannot be opened or read, is not a regular file (a
  // folder, /dev/zero, a pipe), or is larger than `max_bytes`; FileChangedError for one whose
  // size or modification time differ after the read from what they were before it, or that
  // ended early or went on past its size. `after_stat`, for tests, runs between the first
  // check and the read.
  FileInMemory(const std::string& path, std::uint64_t max_bytes,
               const std::function<void()>& after_stat = {});

  std::string_view text() const override { return {bytes_.get(), size_}; }

 private:
  struct Unmap {
    std::size_t bytes;
    void operator()(char* pages) const;
  };
  std::unique_ptr<char, Unmap> bytes_;
  std::size_t size_ = 0;
};

}  // namespace clrt

// Reading files whose errors name the path and the system's reason.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace clrt::image_detail {

class InputFile {
 public:
  explicit InputFile(std::string path);  // throws ImageError if it cannot be opened
  ~InputFile();
  InputFile(const InputFile&) = delete;
  InputFile& operator=(const InputFile&) = delete;

  const std::string& path() const { return path_; }
  std::uint64_t size() const { return size_; }
  // Exactly `size` bytes from the current position; a short file is an ImageError.
  void read_exact(void* data, std::size_t size);

 private:
  std::string path_;
  int fd_ = -1;
  std::uint64_t size_ = 0;
};

std::vector<std::uint8_t> read_file_bytes(const std::string& path);

}  // namespace clrt::image_detail

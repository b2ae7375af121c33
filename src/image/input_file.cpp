#include "image/input_file.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

#include "image/image.hpp"

namespace clrt::image_detail {
namespace {

[[noreturn]] void fail(const std::string& path, const char* step, int error) {
  throw ImageError("cannot read " + path + ": " + step + ": " + std::strerror(error));
}

}  // namespace

InputFile::InputFile(std::string path) : path_(std::move(path)) {
  fd_ = ::open(path_.c_str(), O_RDONLY | O_CLOEXEC);
  if (fd_ < 0) fail(path_, "cannot open", errno);
  struct stat info {};
  if (::fstat(fd_, &info) != 0) {
    const int error = errno;
    ::close(fd_);
    fail(path_, "cannot stat", error);
  }
  if (!S_ISREG(info.st_mode)) {
    ::close(fd_);
    throw ImageError("cannot read " + path_ + ": not a regular file");
  }
  size_ = static_cast<std::uint64_t>(info.st_size);
}

InputFile::~InputFile() { ::close(fd_); }

void InputFile::read_exact(void* data, std::size_t size) {
  auto* bytes = static_cast<char*>(data);
  while (size > 0) {
    const ssize_t got = ::read(fd_, bytes, size);
    if (got < 0) {
      if (errno == EINTR) continue;
      fail(path_, "read error", errno);
    }
    if (got == 0) throw ImageError("cannot read " + path_ + ": the file ended early");
    bytes += got;
    size -= static_cast<std::size_t>(got);
  }
}

std::vector<std::uint8_t> read_file_bytes(const std::string& path) {
  InputFile file(path);
  std::vector<std::uint8_t> bytes(static_cast<std::size_t>(file.size()));
  file.read_exact(bytes.data(), bytes.size());
  return bytes;
}

}  // namespace clrt::image_detail

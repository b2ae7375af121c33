#include "image/input_file.hpp"

#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdint>
#include <cstring>

#include "image/image.hpp"
#include "image/input_file_checks.hpp"

namespace clrt::image_detail {
namespace {

[[noreturn]] void fail(const std::string& path, const char* step, int error) {
  throw ImageError("cannot read " + path + ": " + step + ": " + std::strerror(error));
}

}  // namespace

InputFile::InputFile(std::string path) : path_(std::move(path)) {
  fd_ = open_input_at_once(path_);
  if (fd_ < 0) fail(path_, "cannot open", errno);
  struct stat info {};
  if (::fstat(fd_, &info) != 0) {
    const int error = errno;
    ::close(fd_);
    fail(path_, "cannot stat", error);
  }
  try {
    check_input_status(info, UINT64_MAX);  // no limit in bytes: the header's size is checked
  } catch (const InputFileError& e) {
    ::close(fd_);
    throw NotAFileError("cannot read " + path_ + ": " + e.what());
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

#include "scene/mapped_file.hpp"

#include <fcntl.h>
#include <sys/mman.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

namespace clrt {
namespace {

// Closes the descriptor on every path out of the constructor: the mapping outlives it.
struct Descriptor {
  int fd;
  ~Descriptor() {
    if (fd >= 0) ::close(fd);
  }
};

}  // namespace

MappedFile::MappedFile(const std::string& path, std::uint64_t max_bytes) {
  const auto fail = [&](const std::string& why) { return FileReadError("cannot be read (" + why + ")"); };
  const Descriptor file{::open(path.c_str(), O_RDONLY | O_CLOEXEC)};
  if (file.fd < 0) throw fail(std::strerror(errno));
  struct stat info {};
  if (::fstat(file.fd, &info) != 0) throw fail(std::strerror(errno));
  if (S_ISDIR(info.st_mode)) throw fail("it is a folder");
  if (!S_ISREG(info.st_mode)) throw fail("it is not a regular file");
  if (static_cast<std::uint64_t>(info.st_size) > max_bytes)
    throw fail("it is larger than " + std::to_string(max_bytes >> 20) + " MiB");
  size_ = static_cast<std::size_t>(info.st_size);
  if (size_ == 0) return;  // mmap refuses a length of 0
  // MAP_POPULATE reads the whole file in one request instead of a page fault per page.
  void* data = ::mmap(nullptr, size_, PROT_READ, MAP_PRIVATE | MAP_POPULATE, file.fd, 0);
  if (data == MAP_FAILED) throw fail(std::strerror(errno));
  data_ = static_cast<const char*>(data);
}

MappedFile::~MappedFile() {
  if (data_) ::munmap(const_cast<char*>(data_), size_);
}

}  // namespace clrt

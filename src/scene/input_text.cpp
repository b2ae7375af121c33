#include "scene/input_text.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

namespace clrt {
namespace {

std::string mib(std::uint64_t bytes) { return std::to_string(bytes >> 20) + " MiB"; }

void check_status(const struct stat& info, std::uint64_t max_bytes) {
  if (S_ISDIR(info.st_mode)) throw InputFileError("it is a folder");
  if (!S_ISREG(info.st_mode)) throw InputFileError("it is not a regular file");
  if (static_cast<std::uint64_t>(info.st_size) > max_bytes)
    throw InputFileError("it is " + std::to_string(info.st_size) + " bytes, more than the limit of " +
                         mib(max_bytes));
}

class Descriptor {
 public:
  explicit Descriptor(int fd) : fd_(fd) {}
  ~Descriptor() {
    if (fd_ >= 0) ::close(fd_);
  }
  Descriptor(const Descriptor&) = delete;
  Descriptor& operator=(const Descriptor&) = delete;
  int get() const { return fd_; }

 private:
  int fd_;
};

}  // namespace

void check_input_file(const std::string& path, std::uint64_t max_bytes) {
  struct stat info {};
  if (::stat(path.c_str(), &info) != 0) throw InputFileError(std::strerror(errno));
  check_status(info, max_bytes);
}

std::string read_input_text(const std::string& path, std::uint64_t max_bytes) {
  // O_NONBLOCK: opening a pipe must not wait for a writer before the checks below refuse it.
  const Descriptor file(::open(path.c_str(), O_RDONLY | O_CLOEXEC | O_NONBLOCK));
  if (file.get() < 0) throw InputFileError(std::strerror(errno));
  struct stat info {};
  if (::fstat(file.get(), &info) != 0) throw InputFileError(std::strerror(errno));
  check_status(info, max_bytes);
  std::string text;
  text.reserve(static_cast<std::size_t>(info.st_size));
  char buffer[1 << 16];
  for (;;) {
    const ssize_t got = ::read(file.get(), buffer, sizeof buffer);
    if (got < 0) {
      if (errno == EINTR) continue;
      throw InputFileError(std::string("read error: ") + std::strerror(errno));
    }
    if (got == 0) return text;
    if (text.size() + static_cast<std::size_t>(got) > max_bytes)
      throw InputFileError("it grew past the limit of " + mib(max_bytes) + " while being read");
    text.append(buffer, static_cast<std::size_t>(got));
  }
}

}  // namespace clrt

#include "scene/file_in_memory.hpp"

#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

#include "math/fresh_pages.hpp"
#include "image/input_file_checks.hpp"

namespace clrt {
namespace {

// Closes the descriptor on every path out of the constructor.
struct Descriptor {
  int fd;
  ~Descriptor() {
    if (fd >= 0) ::close(fd);
  }
};

struct stat status_of(int fd) {
  struct stat info {};
  if (::fstat(fd, &info) != 0) throw InputFileError(std::strerror(errno));
  return info;
}

// Reads up to `size` bytes; fewer only at the file's end.
std::size_t read_up_to(int fd, char* to, std::size_t size) {
  std::size_t done = 0;
  while (done < size) {
    const ::ssize_t got = ::read(fd, to + done, size - done);
    if (got < 0 && errno == EINTR) continue;
    if (got < 0) throw InputFileError(std::strerror(errno));
    if (got == 0) break;
    done += static_cast<std::size_t>(got);
  }
  return done;
}

bool same_version(const struct stat& a, const struct stat& b) {
  return a.st_size == b.st_size && a.st_mtim.tv_sec == b.st_mtim.tv_sec &&
         a.st_mtim.tv_nsec == b.st_mtim.tv_nsec;
}

}  // namespace

FileInMemory::FileInMemory(const std::string& path, std::uint64_t max_bytes,
                           const std::function<void()>& after_stat) {
  const Descriptor file{open_input_at_once(path)};
  if (file.fd < 0) throw InputFileError(std::strerror(errno));
  const struct stat before = status_of(file.fd);
  check_input_status(before, max_bytes);
  if (after_stat) after_stat();
  size_ = static_cast<std::size_t>(before.st_size);
  // One byte more than the size: a file that grew gives it.
  const std::size_t room = size_ + 1;
  bytes_ = std::unique_ptr<char, Unmap>(static_cast<char*>(map_fresh_pages(room)), Unmap{room});
  const std::size_t got = read_up_to(file.fd, bytes_.get(), room);
  if (got != size_ || !same_version(before, status_of(file.fd))) throw FileChangedError();
}

void FileInMemory::Unmap::operator()(char* pages) const { unmap_fresh_pages(pages, bytes); }

}  // namespace clrt

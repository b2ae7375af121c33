#include "image/atomic_file.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <cstring>

#include "image/sink_error.hpp"

namespace clrt::image_detail {
namespace {

// A name no other writer uses: the process id keeps processes apart, the counter threads and
// successive writes; O_EXCL catches whatever is left (e.g. a stale temporary from a crash).
std::string next_temp_candidate(const std::string& path) {
  static std::atomic<unsigned> counter{0};
  return path + "." + std::to_string(::getpid()) + "-" + std::to_string(counter++) + ".tmp";
}

}  // namespace

AtomicFile::AtomicFile(std::string path) : path_(std::move(path)) {
  constexpr int kAttempts = 100;
  for (int attempt = 0; attempt < kAttempts; ++attempt) {
    temp_path_ = next_temp_candidate(path_);
    registration_.emplace(temp_path_);
    // Mode 0666 lets the umask decide, as for any newly created file (mkstemp would force 0600).
    fd_ = ::open(temp_path_.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
    if (fd_ >= 0) {
      temp_exists_ = true;
      return;
    }
    const int error = errno;
    registration_.reset();  // an existing file (a leftover of another process) is not ours
    errno = error;
    if (errno != EEXIST) break;
  }
  fail("cannot create temporary");
}

AtomicFile::~AtomicFile() { discard(); }

void AtomicFile::write_through(const void* data, std::size_t size) {
  if (const int error = write_all(fd_, data, size)) {
    errno = error;
    fail("cannot write temporary");
  }
}

void AtomicFile::finish() {
  flush();
  hold_before_commit_for_tests(temp_path_);
  if (::fsync(fd_) != 0) fail("cannot flush temporary");
  const int fd = fd_;
  fd_ = -1;
  // A failed close can mean lost data (e.g. on NFS), so it fails the write.
  if (::close(fd) != 0) fail("cannot close temporary");
  if (::rename(temp_path_.c_str(), path_.c_str()) != 0) fail("cannot rename temporary");
  temp_exists_ = false;
  registration_.reset();
}

void AtomicFile::fail(const char* step) {
  const int error = errno;  // before discard() or any allocation can change it
  discard();
  throw SinkError("cannot write " + path_ + ": " + step + " " + temp_path_ + ": " +
                   std::strerror(error));
}

void AtomicFile::discard() noexcept {
  if (fd_ >= 0) ::close(fd_);
  fd_ = -1;
  if (temp_exists_) ::unlink(temp_path_.c_str());
  temp_exists_ = false;
  registration_.reset();
}

}  // namespace clrt::image_detail

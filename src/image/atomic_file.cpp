#include "image/atomic_file.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <cstdio>
#include <cstring>

#include "image/interrupt_cleanup.hpp"
#include "image/sink_error.hpp"

namespace clrt::image_detail {
namespace {

// A name no other writer uses, short enough for any folder's limit on names (the output's own
// name may already be at that limit): the process id keeps processes apart, the counter threads
// and successive writes; O_EXCL catches whatever is left (e.g. a stale temporary from a crash).
std::string next_temp_candidate(const std::string& path) {
  static std::atomic<unsigned> counter{0};
  const std::string folder = folder_of(path);
  return folder + (folder == "/" ? "" : "/") + ".clrt-" + std::to_string(::getpid()) + "-" +
         std::to_string(counter++) + ".tmp";
}

}  // namespace

void check_replaceable(const std::string& path, const std::string& name) {
  struct stat info {};
  if (::stat(path.c_str(), &info) != 0 || !S_ISREG(info.st_mode)) return;
  const auto refuse = [&](const std::string& why) {
    throw SinkError("cannot write " + name + ": " + why);
  };
  if (::faccessat(AT_FDCWD, path.c_str(), W_OK, AT_EACCESS) != 0 && errno == EACCES) {
    char mode[8];
    std::snprintf(mode, sizeof mode, "%04o", static_cast<unsigned>(info.st_mode & 07777));
    refuse(std::string("it is read-only to you (mode ") + mode + ")");
  }
  if (info.st_nlink > 1)
    refuse("it has " + std::to_string(info.st_nlink) +
           " hard links, and replacing it would leave the others with the old image; remove "
           "this name first, or write another");
}

std::string folder_of(const std::string& path) {
  const std::size_t slash = path.rfind('/');
  if (slash == std::string::npos) return ".";
  return slash == 0 ? "/" : path.substr(0, slash);
}

AtomicFile::AtomicFile(std::string path, std::string name)
    : path_(std::move(path)), name_(std::move(name)) {
  check_replaceable(path_, name_);
  struct stat replaced {};
  const bool replaces = ::stat(path_.c_str(), &replaced) == 0 && S_ISREG(replaced.st_mode);
  constexpr int kAttempts = 100;
  for (int attempt = 0; attempt < kAttempts; ++attempt) {
    temp_path_ = next_temp_candidate(path_);
    int error = 0;
    change_temporary(temp_path_, [&] {
      // Mode 0666 lets the umask decide, as for any new file (mkstemp would force 0600). One
      // that replaces a file starts private, until it has that file's owner and mode.
      fd_ = ::open(temp_path_.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC,
                   replaces ? 0600 : 0666);
      error = errno;
      return fd_ >= 0;
    });
    if (fd_ >= 0) {
      temp_exists_ = true;
      if (replaces) keep_metadata_of(replaced);
      return;
    }
    errno = error;
    if (errno != EEXIST) break;
  }
  fail("cannot create a file in " + folder_of(path_));
}

void AtomicFile::keep_metadata_of(const struct stat& replaced) {
  // Owner before mode: a change of owner clears the set-user-ID and set-group-ID bits. Only
  // root may give a file away; another user keeps the group where the user is in it, and
  // otherwise gets a file of the user's own, as a copy the user made would be. Both are best
  // efforts, as for `cp -p`: a file system without owners or modes (FAT) still takes the image.
  if (::fchown(fd_, replaced.st_uid, replaced.st_gid) != 0)
    (void)!::fchown(fd_, static_cast<uid_t>(-1), replaced.st_gid);
  (void)!::fchmod(fd_, replaced.st_mode & 07777);
}

AtomicFile::~AtomicFile() { discard(); }

void AtomicFile::write_through(const void* data, std::size_t size) {
  if (const int error = write_all(fd_, data, size)) {
    errno = error;
    fail("");
  }
}

void AtomicFile::finish() {
  flush();
  hold_before_commit_for_tests(temp_path_);
  if (::fsync(fd_) != 0) fail("cannot flush it to disk");
  const int fd = fd_;
  fd_ = -1;
  // A failed close can mean lost data (e.g. on NFS), so it fails the write.
  if (::close(fd) != 0) fail("");
  int error = 0;
  change_temporary(temp_path_, [&] {
    temp_exists_ = ::rename(temp_path_.c_str(), path_.c_str()) != 0;
    error = errno;
    return temp_exists_;
  });
  errno = error;
  if (temp_exists_) fail("cannot rename the finished image onto it");
}

void AtomicFile::fail(const std::string& step) {
  const int error = errno;  // before discard() or any allocation can change it
  discard();
  throw SinkError("cannot write " + name_ + ": " + (step.empty() ? "" : step + ": ") +
                  std::strerror(error));
}

void AtomicFile::discard() noexcept {
  if (fd_ >= 0) ::close(fd_);
  fd_ = -1;
  if (temp_exists_)
    change_temporary(temp_path_, [this] {
      ::unlink(temp_path_.c_str());
      return false;
    });
  temp_exists_ = false;
}

}  // namespace clrt::image_detail

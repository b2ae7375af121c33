#include "image/output_target.hpp"

#include <fcntl.h>
#include <limits.h>
#include <sys/stat.h>
#include <sys/statvfs.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

#include "image/atomic_file.hpp"

namespace clrt {
namespace {

constexpr int kMaxLinks = 40;  // as the kernel's own limit when it follows links

[[noreturn]] void refuse(const std::string& path, const std::string& why) {
  throw ImageError("cannot write " + path + ": " + why);
}

}  // namespace

OutputTarget find_output_target(const std::string& path) {
  // Where the links end in a device or FIFO, the path itself is opened: the kernel follows
  // links that readlink() cannot spell, such as /dev/stdout's to a pipe.
  struct stat final_file {};
  if (::stat(path.c_str(), &final_file) == 0 && !S_ISREG(final_file.st_mode) &&
      !S_ISDIR(final_file.st_mode))
    return {path, true};
  std::string at = path;
  for (int links = 0; links <= kMaxLinks; ++links) {
    struct stat info {};
    if (::lstat(at.c_str(), &info) != 0) return {at, false};  // a new file, or refused later
    if (!S_ISLNK(info.st_mode)) return {at, false};
    char target[PATH_MAX];
    const ssize_t size = ::readlink(at.c_str(), target, sizeof target - 1);
    if (size < 0)
      refuse(path, std::string("cannot read the link ") + at + ": " + std::strerror(errno));
    const std::string next(target, static_cast<std::size_t>(size));
    at = next.front() == '/' || at.find('/') == std::string::npos
             ? next
             : at.substr(0, at.rfind('/') + 1) + next;
  }
  refuse(path, "too many levels of symbolic links");
}

void refuse_folder(const std::string& path) {
  struct stat info {};
  if (::stat(path.c_str(), &info) == 0 && S_ISDIR(info.st_mode))
    refuse(path, "it is a folder; name the image file");
}

void check_output_writable(const std::string& path) {
  const OutputTarget target = find_output_target(path);
  if (target.stream) {
    if (::access(target.path.c_str(), W_OK) != 0) refuse(path, std::strerror(errno));
    return;
  }
  refuse_folder(path);
  struct stat info {};
  const std::string folder = image_detail::folder_of(target.path);
  // A missing folder, and a path longer than PATH_MAX (ENAMETOOLONG), are told as the system
  // tells them.
  if (::stat(folder.c_str(), &info) != 0) refuse(path, folder + ": " + std::strerror(errno));
  if (!S_ISDIR(info.st_mode)) refuse(path, folder + " is not a folder");
  // The temporary's short name would pass where the final rename fails.
  const long name_max = ::pathconf(folder.c_str(), _PC_NAME_MAX);
  const std::size_t name_bytes = target.path.size() - target.path.rfind('/') - 1;
  if (name_max > 0 && name_bytes > static_cast<std::size_t>(name_max))
    refuse(path, "its name has " + std::to_string(name_bytes) + " bytes, more than the " +
                     std::to_string(name_max) + " its folder allows");
  image_detail::AtomicFile probe(target.path, path);  // removed again by its destructor
}

void check_output_replaceable(const std::string& path) {
  const OutputTarget target = find_output_target(path);
  if (!target.stream) image_detail::check_replaceable(target.path, path);
}

std::uint64_t free_bytes_for(const std::string& path) {
  struct statvfs info {};
  if (::statvfs(image_detail::folder_of(find_output_target(path).path).c_str(), &info) != 0)
    return UINT64_MAX;  // unknown: the write itself will tell
  const std::uint64_t blocks = ::geteuid() == 0 ? info.f_bfree : info.f_bavail;
  return blocks * info.f_frsize;
}

std::uint64_t minimum_file_bytes(ImageFormat format, std::uint64_t pixels) {
  switch (format) {
    case ImageFormat::Fsf:
      return 4 * pixels;
    case ImageFormat::Ppm:
      return 3 * pixels;
    case ImageFormat::Pfm:
      return 12 * pixels;
    case ImageFormat::Png:
    case ImageFormat::Exr:
      break;
  }
  return 0;
}

namespace image_detail {

std::unique_ptr<ByteSink> open_output_sink(const std::string& path) {
  if (path == kStdoutPath) return std::make_unique<FdSink>(STDOUT_FILENO, "standard output");
  const OutputTarget target = find_output_target(path);
  if (!target.stream) return std::make_unique<AtomicFile>(target.path, path);
  // A FIFO waits here for its reader, as a shell's redirection would.
  const int fd = ::open(target.path.c_str(), O_WRONLY | O_NOCTTY | O_CLOEXEC);
  if (fd < 0) refuse(path, std::strerror(errno));
  return std::make_unique<FdSink>(fd, path, true);
}

std::unique_ptr<ByteSink> open_output_sink(const ImageOutput& output) { return open_output_sink(output.path); }

}  // namespace image_detail
}  // namespace clrt

#include "scene/scene_image.hpp"

#include <unistd.h>

#include <array>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <memory>
#include <stdexcept>
#include <string_view>

namespace clrt {
namespace {

// Removes a file when it goes out of scope.
struct RemovedAtExit {
  std::string path;
  ~RemovedAtExit() { std::remove(path.c_str()); }
};

// The decoders read files, so the bytes pass through a private temporary copy with the same
// extension (which names the format).
}  // namespace

AnyImage read_scene_image(const FileSource& files, const std::string& path, std::uint64_t max_bytes,
                          const std::function<void(const ImageInfo&)>& check_header) {
  const std::unique_ptr<FileBytes> bytes = files.open(path, max_bytes);
  const std::string extension = std::filesystem::path(path).extension().string();
  const char* folder = std::getenv("TMPDIR");
  std::string name = std::string(folder && *folder ? folder : "/tmp") + "/clrt-image-XXXXXX" + extension;
  const int fd = mkstemps(name.data(), static_cast<int>(extension.size()));
  if (fd < 0) throw std::runtime_error("cannot make a temporary copy: " + std::string(std::strerror(errno)));
  const RemovedAtExit copy{name};
  std::string_view left = bytes->text();
  while (!left.empty()) {
    const ssize_t n = ::write(fd, left.data(), left.size());
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) {
      ::close(fd);
      throw std::runtime_error("cannot write a temporary copy: " + std::string(std::strerror(errno)));
    }
    left.remove_prefix(static_cast<std::size_t>(n));
  }
  ::close(fd);
  try {
    if (check_header) check_header(read_image_info(name));
    return read_any_image(name);
  } catch (const std::exception& e) {
    // The decoders' messages name the file they read: the user's, not the copy.
    std::string message = e.what();
    for (std::size_t at = message.find(name); at != std::string::npos; at = message.find(name, at + path.size()))
      message.replace(at, name.size(), path);
    throw std::runtime_error(message);
  }
}


const std::array<float, 256>& srgb_linear_values() {
  static const std::array<float, 256> values = [] {
    std::array<float, 256> v{};
    for (std::size_t code = 0; code < v.size(); ++code) {
      const double c = static_cast<double>(code) / 255.0;
      v[code] = static_cast<float>(c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4));
    }
    return v;
  }();
  return values;
}

float srgb_to_linear(std::uint8_t code) { return srgb_linear_values()[code]; }

}  // namespace clrt

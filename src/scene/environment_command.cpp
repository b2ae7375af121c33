// environment FILE [SCALE]: the image of the radiance arriving from every direction.
#include <unistd.h>

#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <memory>
#include <string_view>
#include <variant>

#include "image/image.hpp"
#include "scene/command_table.hpp"
#include "scene/file_source.hpp"
#include "scene/limits.hpp"

namespace clrt {
namespace {

// PNG and PPM hold sRGB-encoded 8-bit values; the renderer wants radiance.
float srgb_decode(std::uint8_t byte) {
  const double c = byte / 255.0;
  return static_cast<float>(c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4));
}

// The linear part of `m` as a rotation (orthonormal columns, determinant 1) within 1e-6; the map
// turns with it, and a scale or shear would have no meaning for directions.
bool is_rotation(const Mat4& m) {
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      if (std::fabs(dot(m.column(i), m.column(j)) - (i == j ? 1.0 : 0.0)) > 1e-6) return false;
  return m.determinant() > 0;
}

// Removes a file when it goes out of scope.
struct RemovedAtExit {
  std::string path;
  ~RemovedAtExit() { std::remove(path.c_str()); }
};

// The image at `path`, its bytes taken from `files` as a mesh's are, so that an MPI rank gets
// them from rank 0 rather than from a disk of its own; the decoders read files, so the bytes
// pass through a private temporary copy with the same extension (which names the format).
AnyImage read_through(const FileSource& files, const std::string& path, std::uint64_t max_bytes) {
  const std::unique_ptr<FileBytes> bytes = files.open(path, max_bytes);
  const std::string extension = std::filesystem::path(path).extension().string();
  const char* folder = std::getenv("TMPDIR");
  std::string name = std::string(folder && *folder ? folder : "/tmp") + "/clrt-environment-XXXXXX" + extension;
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
    return read_any_image(name);
  } catch (const std::exception& e) {
    // The decoders' messages name the file they read: the user's, not the copy.
    std::string message = e.what();
    for (std::size_t at = message.find(name); at != std::string::npos; at = message.find(name, at + path.size()))
      message.replace(at, name.size(), path);
    throw std::runtime_error(message);
  }
}

void environment(LoaderState& s, const CommandArgs& a) {
  a.require_count({1, 2});
  EnvironmentSpec env;
  env.path = (std::filesystem::path(s.scene_folder) / a.word(0).text).lexically_normal().generic_string();
  if (a.count() > 1) env.scale = a.number_in(1, 0, limits::kMaxNumber, "the environment's scale");
  if (in_motion(s))
    throw a.error_at(0, "the environment cannot move: it turns with the current transform, which "
                        "differs from the one `endpose` recorded; put `environment` before "
                        "`endpose` or after `reset`");
  if (!is_rotation(s.transform))
    throw a.error_at(0, "the environment turns with the current transform, whose linear part must "
                        "be a rotation (no scale or shear); put `environment` before them or after "
                        "`reset`");
  env.rotation = s.transform;
  AnyImage image;
  try {
    image = read_through(*s.files, env.path, s.memory.bytes);
  } catch (const std::exception& e) {
    throw a.error_at(0, "cannot read the environment image " + excerpt(env.path) + ": " + e.what());
  }
  if (const auto* bytes = std::get_if<Rgba8Image>(&image)) {
    env.width = bytes->width;
    env.height = bytes->height;
    const std::vector<std::uint8_t>& rgba = bytes->frames.at(0);
    env.rgb.resize(rgba.size() / 4 * 3);
    for (std::size_t i = 0; i < env.rgb.size(); ++i) env.rgb[i] = srgb_decode(rgba[i + i / 3]);
  } else {
    FloatImage& floats = std::get<FloatImage>(image);
    env.width = floats.width;
    env.height = floats.height;
    env.rgb = std::move(floats.rgb);
  }
  for (std::size_t i = 0; i < env.rgb.size(); ++i) {
    const float v = env.rgb[i];
    if (!(v >= 0 && v <= limits::kMaxNumber)) {
      const std::size_t pixel = i / 3;
      throw a.error_at(0, "the environment image " + excerpt(env.path) + " has the radiance " +
                              short_number(v) + " at pixel (" + std::to_string(pixel % env.width) + ", " +
                              std::to_string(pixel / env.width) + "): each channel must be in [0, " +
                              short_number(limits::kMaxNumber) + "]");
    }
  }
  s.scene.environment = std::move(env);
}

}  // namespace

void add_environment_command(CommandTable& table) { table["environment"] = environment; }

}  // namespace clrt

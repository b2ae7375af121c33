#include "scene/texture_images.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <variant>

#include "scene/limits.hpp"
#include "scene/scene_image.hpp"
#include "scene/scene_memory.hpp"

namespace clrt {

std::uint64_t texture_device_bytes(std::int64_t width, std::int64_t height, bool linear) {
  std::uint64_t texels = 0;
  for (;;) {
    texels += static_cast<std::uint64_t>(width) * static_cast<std::uint64_t>(height);
    if (width == 1 && height == 1) break;
    width = std::max<std::int64_t>(width / 2, 1);
    height = std::max<std::int64_t>(height / 2, 1);
  }
  return texels * (linear ? 12 : 4);
}

std::uint64_t texture_source_bytes(std::int64_t width, std::int64_t height, bool linear) {
  return static_cast<std::uint64_t>(width) * static_cast<std::uint64_t>(height) * (linear ? 12 : 4);
}

std::uint64_t texture_image_bytes(std::int64_t width, std::int64_t height, bool linear) {
  return texture_source_bytes(width, height, linear) + 2 * texture_device_bytes(width, height, linear);
}

std::uint64_t texture_image_bytes(const TextureImage& image) {
  return texture_image_bytes(image.width, image.height, image.linear);
}

void check_image_side(const ImageInfo& info, const std::string& what) {
  if (info.width > kMaxTextureSide || info.height > kMaxTextureSide)
    throw std::runtime_error("it is " + std::to_string(info.width) + "x" + std::to_string(info.height) +
                             " pixels; " + what + " may have at most " + std::to_string(kMaxTextureSide) +
                             " on a side");
}

void check_image_memory(std::uint64_t needed, const MemoryLimit& memory) {
  if (needed > memory.bytes)
    throw std::runtime_error("the scene with it would need " + mebibytes(needed) + ", " +
                             mebibytes(memory.bytes) + " available (" + memory.source + ")");
}

namespace {

// The 8-bit RGBA frame's RGB moved to its front in place: a second buffer would double the peak
// of the largest textures.
TextureImage decoded(AnyImage image, const std::string& path) {
  TextureImage t;
  t.path = path;
  if (auto* bytes = std::get_if<Rgba8Image>(&image)) {
    t.width = bytes->width;
    t.height = bytes->height;
    t.srgb = std::move(bytes->frames.at(0));
    const std::size_t texels = t.srgb.size() / 4;
    for (std::size_t i = 0; i < texels; ++i)
      for (std::size_t c = 0; c < 3; ++c) t.srgb[3 * i + c] = t.srgb[4 * i + c];
    t.srgb.resize(3 * texels);
  } else {
    FloatImage& floats = std::get<FloatImage>(image);
    t.width = floats.width;
    t.height = floats.height;
    t.linear = true;
    t.rgb = std::move(floats.rgb);
  }
  return t;
}

}  // namespace

int texture_image(LoaderState& s, const std::string& path, const SourceLocation& where) {
  for (std::size_t i = 0; i < s.scene.texture_images.size(); ++i)
    if (s.scene.texture_images[i].path == path) return static_cast<int>(i);
  const std::string named = "the texture image " + excerpt(path);
  const std::uint64_t used = loader_bytes(s);
  // What the header declares decides what is allocated: it is checked first. While it decodes,
  // the file and the decoded texels are held together.
  const auto check_header = [&](const ImageInfo& info, std::uint64_t file_bytes) {
    check_image_side(info, "a texture");
    const bool linear = holds_floats(info.format);
    check_image_memory(used + std::max(file_bytes + texture_source_bytes(info.width, info.height, linear),
                                       texture_image_bytes(info.width, info.height, linear)),
                       s.memory);
  };
  TextureImage image;
  try {
    image = decoded(read_scene_image(*s.files, path, s.memory.bytes, check_header), path);
  } catch (const SceneError&) {
    throw;
  } catch (const std::exception& e) {
    throw SceneError(where, "cannot use " + named + ": " + e.what());
  }
  for (std::size_t i = 0; i < image.rgb.size(); ++i) {
    const float v = image.rgb[i];
    if (!(v >= 0 && v <= limits::kMaxNumber)) {
      const std::size_t texel = i / 3;
      throw SceneError(where, named + " has the value " + short_number(v) + " at pixel (" +
                                  std::to_string(texel % image.width) + ", " +
                                  std::to_string(texel / image.width) + "): each channel must be in [0, " +
                                  short_number(limits::kMaxNumber) + "]");
    }
  }
  s.scene.texture_images.push_back(std::move(image));
  return static_cast<int>(s.scene.texture_images.size()) - 1;
}

}  // namespace clrt

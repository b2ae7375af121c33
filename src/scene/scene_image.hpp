// Images a scene names (an environment, a texture), read through the scene's FileSource.
#pragma once

#include <array>
#include <cstdint>
#include <functional>
#include <string>

#include "image/image.hpp"
#include "image/image_info.hpp"
#include "scene/file_source.hpp"

namespace clrt {

// Sees what a header declares, and the file's size, before a pixel is decoded; throws to refuse.
using HeaderCheck = std::function<void(const ImageInfo& info, std::uint64_t file_bytes)>;

// The first frame of the image at `path`, its bytes taken from `files` as a mesh's are, so that
// an MPI rank gets them from rank 0 rather than from a disk of its own, and decoded where they
// lie: no copy is made, on a disk or elsewhere. Messages name `path`.
AnyImage read_scene_image(const FileSource& files, const std::string& path, std::uint64_t max_bytes,
                          const HeaderCheck& check_header = {});

// The linear value of an 8-bit sRGB code (PNG and PPM hold sRGB; the renderer wants linear),
// from a table worked out once: a 2048x2048 image's channels through std::pow took seconds.
float srgb_to_linear(std::uint8_t code);
// That table, increasing with the code.
const std::array<float, 256>& srgb_linear_values();

}  // namespace clrt

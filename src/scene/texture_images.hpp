// The images textures show: read once per file, checked from their headers before anything is
// decoded, and counted with the scene's memory.
#pragma once

#include <cstdint>
#include <string>

#include "image/image_info.hpp"
#include "scene/loader_state.hpp"
#include "scene/memory_limit.hpp"
#include "scene/scene.hpp"
#include "scene/source_location.hpp"

namespace clrt {

// The longest side a texture or environment image may have, in pixels.
constexpr std::int64_t kMaxTextureSide = 16384;

// The bytes of an image of width x height texels on the device, with its mip levels (each at
// most a quarter of the one before): 4 per texel for 8-bit images, 12 for linear ones.
std::uint64_t texture_device_bytes(std::int64_t width, std::int64_t height, bool linear);

// The bytes the decoded texels of such an image hold on the host while the scene lives: 4 a
// texel for 8-bit images (their RGB kept in the decoder's RGBA buffer), 12 for linear ones.
std::uint64_t texture_source_bytes(std::int64_t width, std::int64_t height, bool linear);

// The bytes an image of width x height texels takes from its load to its render: its decoded
// texels, and its mip levels twice, as the host builds them and as the device holds them.
std::uint64_t texture_image_bytes(std::int64_t width, std::int64_t height, bool linear);
std::uint64_t texture_image_bytes(const TextureImage& image);

// Refuses (std::runtime_error) an image header whose side passes kMaxTextureSide; `what` is
// "a texture" or "an environment".
void check_image_side(const ImageInfo& info, const std::string& what);
// Refuses `needed` bytes beyond `memory`, saying what the scene would need.
void check_image_memory(std::uint64_t needed, const MemoryLimit& memory);

// The index into s.scene.texture_images of the image at `path` (as resolved), read on its first
// use. A file that cannot be read, is no image clrt reads, has a side beyond kMaxTextureSide, would
// pass the memory left, or holds a value that is not finite and >= 0 is a SceneError at `where`.
int texture_image(LoaderState& s, const std::string& path, const SourceLocation& where);

}  // namespace clrt

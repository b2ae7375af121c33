// The scene's textures in the layout kernels/shared/texture.h gives: a record per texture and one
// table of texel words, the sRGB decoding table first, then every image's mip levels.
#pragma once

#include <vector>

#include "geometry/device_tables.hpp"
#include "scene/scene.hpp"
#include "shared/texture.h"

namespace clrt {

struct TextureTable {
  std::vector<dev::Texture> records;  // row 0 unread (CLRT_NO_TEXTURE), then Scene::textures
  DeviceTable<dev::u32> texels;
};

// Each image's levels are made once, however many textures show it. Level k + 1 averages each
// 2x2 block of level k (the last row or column of an odd size with itself), in linear values;
// an 8-bit image's levels stay 8-bit, each texel the sRGB code whose value is nearest.
TextureTable make_texture_table(const Scene& scene);

// The row of Scene::textures[index] in the table.
inline dev::u32 texture_row(int index) { return static_cast<dev::u32>(index) + 1; }

// Whether the scene's table holds any texture.
inline bool has_textures(const TextureTable& table) { return table.records.size() > 1; }

}  // namespace clrt

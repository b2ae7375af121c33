#include "scene/scene_image.hpp"

#include <array>
#include <cmath>

namespace clrt {

AnyImage read_scene_image(const FileSource& files, const std::string& path, std::uint64_t max_bytes,
                          const HeaderCheck& check_header) {
  const ImageFormat format = format_from_path(path);
  const std::unique_ptr<FileBytes> held = files.open(path, max_bytes);
  const ImageBytes file{ByteSpan(held->text()), path};
  if (check_header) check_header(decode_image_info(file, format), file.bytes.size());
  return decode_image(file, format, Frames::First);
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

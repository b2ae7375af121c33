#include <algorithm>
#include <cctype>
#include <iterator>

#include "image/image.hpp"

namespace clrt {
namespace {

struct NamedFormat {
  const char* extension;
  ImageFormat format;
};

constexpr NamedFormat kFormats[] = {{".fsf", ImageFormat::Fsf},
                                    {".png", ImageFormat::Png},
                                    {".ppm", ImageFormat::Ppm},
                                    {".pfm", ImageFormat::Pfm}};

std::string supported_list() {
  std::string list;
  for (const NamedFormat& named : kFormats)
    list += (list.empty() ? "" : ", ") + std::string(named.extension);
  return list;
}

// The final path component's extension, lower-cased; empty if it has none.
std::string lower_extension(const std::string& path) {
  const std::size_t slash = path.find_last_of('/');
  const std::size_t dot = path.find_last_of('.');
  if (dot == std::string::npos || (slash != std::string::npos && dot < slash)) return {};
  std::string extension = path.substr(dot);
  std::transform(extension.begin(), extension.end(), extension.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return extension;
}

}  // namespace

ImageFormat format_from_path(const std::string& path) {
  const std::string extension = lower_extension(path);
  const auto found =
      std::find_if(std::begin(kFormats), std::end(kFormats),
                   [&](const NamedFormat& named) { return extension == named.extension; });
  if (found != std::end(kFormats)) return found->format;
  const std::string what =
      extension.empty() ? "has no extension" : "has the unknown extension " + extension;
  throw ImageError(path + ": " + what + "; supported image types: " + supported_list());
}

}  // namespace clrt

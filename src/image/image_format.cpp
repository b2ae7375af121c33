#include <algorithm>
#include <cctype>
#include <iterator>

#include "image/image.hpp"

namespace clrt {
namespace {

struct NamedFormat {
  const char* name;
  ImageFormat format;
};

constexpr NamedFormat kFormats[] = {{"fsf", ImageFormat::Fsf},
                                    {"png", ImageFormat::Png},
                                    {"ppm", ImageFormat::Ppm},
                                    {"pfm", ImageFormat::Pfm},
                                    {"exr", ImageFormat::Exr}};

std::string lower(std::string text) {
  std::transform(text.begin(), text.end(), text.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return text;
}

// The final path component's extension with its dot, lower-cased; empty if it has none.
std::string lower_extension(const std::string& path) {
  const std::size_t slash = path.find_last_of('/');
  const std::size_t dot = path.find_last_of('.');
  if (dot == std::string::npos || (slash != std::string::npos && dot < slash)) return {};
  return lower(path.substr(dot));
}

const NamedFormat* find_name(const std::string& name) {
  const auto found = std::find_if(std::begin(kFormats), std::end(kFormats),
                                  [&](const NamedFormat& named) { return name == named.name; });
  return found == std::end(kFormats) ? nullptr : found;
}

std::string supported_list(const char* prefix) {
  std::string list;
  for (const NamedFormat& named : kFormats)
    list += (list.empty() ? "" : ", ") + std::string(prefix) + named.name;
  return list;
}

}  // namespace

std::optional<ImageFormat> format_of_extension(const std::string& path) {
  const std::string extension = lower_extension(path);
  const NamedFormat* named = extension.empty() ? nullptr : find_name(extension.substr(1));
  if (!named) return std::nullopt;
  return named->format;
}

ImageFormat format_from_path(const std::string& path) {
  if (const auto format = format_of_extension(path)) return *format;
  const std::string extension = lower_extension(path);
  const std::string what =
      extension.empty() ? "has no extension" : "has the unknown extension " + extension;
  throw ImageError(path + ": " + what + "; supported image types: " + supported_list("."));
}

ImageFormat format_from_name(const std::string& name) {
  if (const NamedFormat* named = find_name(lower(name))) return named->format;
  throw ImageError("unknown image format \"" + name + "\"; supported: " + supported_list(""));
}

std::string format_name(ImageFormat format) {
  for (const NamedFormat& named : kFormats)
    if (named.format == format) return named.name;
  return "?";
}

std::vector<std::string> format_names() {
  std::vector<std::string> names;
  for (const NamedFormat& named : kFormats) names.emplace_back(named.name);
  return names;
}

bool holds_floats(ImageFormat format) {
  return format == ImageFormat::Pfm || format == ImageFormat::Exr;
}

}  // namespace clrt

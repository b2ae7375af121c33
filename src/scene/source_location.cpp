#include "scene/source_location.hpp"

#include <utility>

namespace clrt {
namespace {

std::string position_of(const SourceLocation& where) {
  if (where.line == 0) return where.file;
  return where.file + ":" + std::to_string(where.line) + ":" + std::to_string(where.column);
}

}  // namespace

std::string scene_warning(const SourceLocation& where, const std::string& message) {
  return position_of(where) + ": warning: " + message;
}

SceneError::SceneError(SourceLocation where, const std::string& message)
    : std::runtime_error(position_of(where) + ": error: " + message),
      where_(std::move(where)),
      message_(message) {}

}  // namespace clrt

#include "scene/source_location.hpp"

#include <utility>

namespace clrt {

SceneError::SceneError(SourceLocation where, const std::string& message)
    : std::runtime_error(where.file + ":" + std::to_string(where.line) + ":" +
                         std::to_string(where.column) + ": error: " + message),
      where_(std::move(where)),
      message_(message) {}

}  // namespace clrt

// Where in an input file something was written, and the error that carries it.
#pragma once

#include <stdexcept>
#include <string>
#include <utility>

namespace clrt {

struct SourceLocation {
  std::string file;  // as the user named it (scene path, or mesh path as resolved)
  int line = 1;      // 1-based
  int column = 1;    // 1-based, counting bytes; line and column 0: the file as a whole

  // A fault of the whole file (it cannot be read, it is no scene at all), which has no line
  // to point at.
  static SourceLocation whole_file(std::string file) { return {std::move(file), 0, 0}; }
};

// What a loader read but cannot use as written: "FILE:LINE:COLUMN: warning: MESSAGE" (Scene::
// warnings), placed as a SceneError is.
std::string scene_warning(const SourceLocation& where, const std::string& message);

// A bad scene or mesh: what() is "FILE:LINE:COLUMN: error: MESSAGE", or "FILE: error: MESSAGE"
// for the file as a whole.
class SceneError : public std::runtime_error {
 public:
  SceneError(SourceLocation where, const std::string& message);
  const SourceLocation& where() const { return where_; }
  const std::string& message() const { return message_; }

 private:
  SourceLocation where_;
  std::string message_;
};

}  // namespace clrt

// Where in an input file something was written, and the error that carries it.
#pragma once

#include <stdexcept>
#include <string>

namespace clrt {

struct SourceLocation {
  std::string file;  // as the user named it (scene path, or mesh path as resolved)
  int line = 1;      // 1-based
  int column = 1;    // 1-based, counting bytes
};

// A bad scene or mesh: what() is "FILE:LINE:COLUMN: error: MESSAGE".
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

// Helpers for loader tests: scene text written to a private scratch directory, and the error
// a load throws.
#pragma once

#include <catch2/catch.hpp>
#include <stdexcept>
#include <string>

#include "scene/scene.hpp"
#include "scratch_dir.hpp"

namespace clrt::test {

// `name` picks the format by its extension, as for any scene file.
inline Scene load_text(const std::string& text, const std::string& name = "scene.ray") {
  ScratchDir dir;
  return load_scene(dir.write(name, text));
}

// The SceneError that loading `path` throws; the test fails (with an unexpected exception) if
// the file loads.
inline SceneError load_error_of_file(const std::string& path) {
  try {
    load_scene(path);
  } catch (const SceneError& e) {
    return e;
  }
  throw std::runtime_error("expected " + path + " to be rejected, but it loaded");
}

inline SceneError load_error(const std::string& text, const std::string& name = "scene.ray") {
  ScratchDir dir;
  return load_error_of_file(dir.write(name, text));
}

// Checks that `text` (written to a file called `name`) is rejected at (line, column) with a
// message containing `part`.
inline void require_error(const std::string& text, int line, int column, const std::string& part,
                          const std::string& name = "scene.ray") {
  const SceneError e = load_error(text, name);
  INFO(e.what());
  CHECK(e.where().line == line);
  CHECK(e.where().column == column);
  CHECK_THAT(e.message(), Catch::Contains(part, Catch::CaseSensitive::No));
}

}  // namespace clrt::test

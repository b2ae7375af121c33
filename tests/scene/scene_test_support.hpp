// Helpers for loader tests: scene text written to a private temporary folder, and the error
// a load throws.
#pragma once

#include <catch2/catch.hpp>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <string>

#include "scene/scene.hpp"

namespace clrt::test {

// A fresh folder under the system's temporary folder, removed with everything in it.
class TempFolder {
 public:
  TempFolder() {
    std::string pattern = (std::filesystem::temp_directory_path() / "clrt-scene-XXXXXX").string();
    if (!mkdtemp(pattern.data())) FAIL("cannot create a temporary folder");
    path_ = pattern;
  }
  ~TempFolder() {
    std::error_code ignored;
    std::filesystem::remove_all(path_, ignored);
  }
  TempFolder(const TempFolder&) = delete;
  TempFolder& operator=(const TempFolder&) = delete;

  // Writes `text` byte for byte to `name` inside the folder; returns its path.
  std::string write(const std::string& name, const std::string& text) const {
    const std::filesystem::path file = path_ / name;
    std::filesystem::create_directories(file.parent_path());
    std::ofstream(file, std::ios::binary) << text;
    return file.string();
  }
  std::string path(const std::string& name) const { return (path_ / name).string(); }

 private:
  std::filesystem::path path_;
};

inline Scene load_text(const std::string& text) {
  TempFolder folder;
  return load_scene(folder.write("scene.ray", text));
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

inline SceneError load_error(const std::string& text) {
  TempFolder folder;
  return load_error_of_file(folder.write("scene.ray", text));
}

// Checks that `text` is rejected at (line, column) with a message containing `part`.
inline void require_error(const std::string& text, int line, int column, const std::string& part) {
  const SceneError e = load_error(text);
  INFO(e.what());
  CHECK(e.where().line == line);
  CHECK(e.where().column == column);
  CHECK_THAT(e.message(), Catch::Contains(part, Catch::CaseSensitive::No));
}

}  // namespace clrt::test

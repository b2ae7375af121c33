// A scene or mesh file that someone shrinks, extends or rewrites while clrt reads it is an error
// that names the file, never a signal nor a scene made of two versions.
#include <catch2/catch.hpp>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <functional>
#include <string>

#include "scene/file_in_memory.hpp"
#include "image/input_file_checks.hpp"
#include "scene/scene.hpp"
#include "scratch_dir.hpp"

using namespace clrt;
namespace fs = std::filesystem;

namespace {

// The disk, where one file is changed by `change` once it has been checked and before its bytes
// are read.
class ChangingFiles final : public FileSource {
 public:
  ChangingFiles(std::string path, std::function<void(const std::string&)> change)
      : path_(std::move(path)), change_(std::move(change)) {}

  std::unique_ptr<FileBytes> open(const std::string& path, std::uint64_t max_bytes) const override {
    if (path != path_) return std::make_unique<FileInMemory>(path, max_bytes);
    return std::make_unique<FileInMemory>(path, max_bytes, [&] { change_(path); });
  }

 private:
  std::string path_;
  std::function<void(const std::string&)> change_;
};

void shrink(const std::string& path) { fs::resize_file(path, fs::file_size(path) / 2); }

void extend(const std::string& path) { std::ofstream(path, std::ios::app) << "v 9 9 9\n"; }

// The same bytes but one, and a modification time that differs from the one checked.
void rewrite(const std::string& path) {
  const auto checked = fs::last_write_time(path);
  std::fstream(path, std::ios::in | std::ios::out) << "#";
  fs::last_write_time(path, checked - std::chrono::seconds(10));
}

const char* const kMesh = "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\nf 1 2 3\nf 2 4 3\n";

}  // namespace

TEST_CASE("a mesh that shrinks, grows or is rewritten while read is an error naming it",
          "[scene][files][errors]") {
  for (const auto& change : {shrink, extend, rewrite}) {
    test::ScratchDir dir;
    const std::string scene = dir.write("s.ray", "sphere 0 0 0 1\nmesh m.obj\n");
    const std::string mesh = dir.write("m.obj", kMesh);
    CHECK_THROWS_WITH(load_scene(scene, ChangingFiles(mesh, change)),
                      scene + ":2:1: error: bad mesh file " + mesh + ": changed while being read");
  }
}

TEST_CASE("a scene file that shrinks, grows or is rewritten while read is an error of the whole file",
          "[scene][files][errors]") {
  for (const auto& change : {shrink, extend, rewrite}) {
    test::ScratchDir dir;
    const std::string scene = dir.write("s.ray", "sphere 0 0 0 1\nsphere 3 0 0 1\n");
    CHECK_THROWS_WITH(load_scene(scene, ChangingFiles(scene, change)),
                      scene + ": error: changed while being read");
  }
}

TEST_CASE("a file left alone reads whole, the same bytes", "[scene][files]") {
  test::ScratchDir dir;
  const std::string mesh = dir.write("m.obj", kMesh);
  CHECK(FileInMemory(mesh, 1 << 20, [] {}).text() == kMesh);
  CHECK(FileInMemory(dir.write("empty.obj", ""), 1 << 20).text().empty());
}

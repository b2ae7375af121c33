// A private scratch directory for tests that write files. Header-only and free of OpenCL, so
// every test binary can use it (CMake target clrt_test_files).
#pragma once

#include <unistd.h>

#include <atomic>
#include <filesystem>
#include <fstream>
#include <set>
#include <stdexcept>
#include <string>

namespace clrt::test {

// A fresh directory under the system's temporary directory, removed with everything in it at the
// end of the scope. The name holds the process id and a counter, so test binaries running in
// parallel never share one. Tests run with the source tree as working directory, so they never
// write relative paths.
class ScratchDir {
 public:
  ScratchDir() {
    static std::atomic<unsigned> counter{0};
    path_ = std::filesystem::temp_directory_path() /
            ("clrt-test-" + std::to_string(::getpid()) + "-" + std::to_string(counter++));
    // A directory left by an earlier process with the same id must not leak into this test.
    std::filesystem::remove_all(path_);
    std::filesystem::create_directories(path_);
  }
  ~ScratchDir() {
    std::error_code ignored;
    std::filesystem::remove_all(path_, ignored);
  }
  ScratchDir(const ScratchDir&) = delete;
  ScratchDir& operator=(const ScratchDir&) = delete;

  const std::filesystem::path& path() const { return path_; }
  std::string file(const std::string& name) const { return (path_ / name).string(); }

  // Writes `text` byte for byte to `name` (which may hold subdirectories); returns its path.
  std::string write(const std::string& name, const std::string& text) const {
    const std::filesystem::path file = path_ / name;
    std::filesystem::create_directories(file.parent_path());
    std::ofstream out(file, std::ios::binary);
    out << text;
    if (!out) throw std::runtime_error("test cannot write " + file.string());
    return file.string();
  }

  // The names directly inside the directory, to show what a run left behind.
  std::set<std::string> entries() const {
    std::set<std::string> names;
    for (const auto& entry : std::filesystem::directory_iterator(path_))
      names.insert(entry.path().filename().string());
    return names;
  }

 private:
  std::filesystem::path path_;
};

}  // namespace clrt::test

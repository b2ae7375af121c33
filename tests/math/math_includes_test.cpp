// src/math/ is the bottom of the host's house: every area builds on it, so it includes only its
// own headers and the system's, never another area's or the kernels' shared records.
#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>
#include <string>

namespace fs = std::filesystem;

TEST_CASE("src/math includes no header of another area or of the kernels", "[math][layout]") {
  const fs::path math = fs::path(CLRT_SOURCE_DIR) / "src" / "math";
  int files = 0;
  for (const auto& entry : fs::directory_iterator(math)) {
    if (!entry.is_regular_file()) continue;
    ++files;
    std::ifstream in(entry.path());
    std::string line;
    for (int number = 1; std::getline(in, line); ++number) {
      if (line.rfind("#include \"", 0) != 0) continue;
      INFO(entry.path().filename().string() << ":" << number << ": " << line);
      CHECK(line.rfind("#include \"math/", 0) == 0);
    }
  }
  CHECK(files > 5);
}

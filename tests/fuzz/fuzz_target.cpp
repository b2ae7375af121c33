// One libFuzzer target: CLRT_FUZZ_PATH names the fuzz_paths.hpp function the input goes through
// and CLRT_FUZZ_FILE the name the input is written to (its extension picks the reader). See
// CMakeLists.txt.
#include <cstddef>
#include <cstdint>

#include "fuzz_input_file.hpp"
#include "fuzz_paths.hpp"

namespace {

// Beside every input: the mesh `mesh mesh.obj` in a fuzzed scene names, so that scenes reach
// the instancing paths.
const char kMesh[] =
    "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\n"
    "vn 0 0 1\nvn 1 0 0\nvn 0 1 0\nvn 0 0 1\n"
    "f 1//1 2//2 3//3\nf 1//1 3//3 4//4\nf 2 3 4 1\n";

}  // namespace

extern "C" int LLVMFuzzerInitialize(int*, char***) {
  clrt::fuzz::write_input("mesh.obj", reinterpret_cast<const std::uint8_t*>(kMesh), sizeof kMesh - 1);
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  clrt::fuzz::CLRT_FUZZ_PATH(clrt::fuzz::write_input(CLRT_FUZZ_FILE, data, size));
  return 0;
}

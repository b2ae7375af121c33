// One image reader on arbitrary bytes. CLRT_FUZZ_READER names the reader (read_fsf, read_ppm,
// read_png, ...) and CLRT_FUZZ_EXTENSION the file name's extension; see CMakeLists.txt.
// A rejected file is an ImageError; anything else escaping, or a sanitizer report, is a finding.
#include <cstddef>
#include <cstdint>

#include "fuzz_input_file.hpp"
#include "image/image.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string path = clrt::fuzz::write_input("input." CLRT_FUZZ_EXTENSION, data, size);
  try {
    const clrt::Rgba8Image image = clrt::CLRT_FUZZ_READER(path);
    // A reader that accepts a file must describe a consistent image.
    for (const auto& frame : image.frames)
      if (frame.size() != 4 * static_cast<std::size_t>(image.width) * static_cast<std::size_t>(image.height))
        __builtin_trap();
  } catch (const clrt::ImageError&) {
  }
  return 0;
}

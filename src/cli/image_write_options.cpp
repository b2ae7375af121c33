#include "cli/image_write_options.hpp"

#include <iostream>

namespace clrt {

WriteOptions image_write_options(ExrPixel exr_pixel, const DisplayTransform& display,
                                 const std::string& program) {
  WriteOptions options{exr_pixel};
  options.display = display;
  options.warn = [program](const std::string& message) {
    std::cerr << program << ": warning: " << message << "\n";
  };
  return options;
}

}  // namespace clrt

// How clrt and clrt-mpi write their images.
#pragma once

#include <string>

#include "image/image.hpp"

namespace clrt {

// The EXR pixel type and the display transform asked for; what the format could not hold as
// "PROGRAM: warning: ..." on standard error.
WriteOptions image_write_options(ExrPixel exr_pixel, const DisplayTransform& display,
                                 const std::string& program);

}  // namespace clrt

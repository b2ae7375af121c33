// The error of a failing output (the file or descriptor): its message already names the output,
// so write_image passes it on as it is, where it prefixes an encoder's errors with the path.
#pragma once

#include "image/image.hpp"

namespace clrt::image_detail {

class SinkError : public ImageError {
 public:
  using ImageError::ImageError;
};

}  // namespace clrt::image_detail

#include "image/png_errors.hpp"

#include <cstring>
#include <string>

#include "image/image.hpp"

namespace clrt::image_detail {

void png_record_error(png_structp png, png_const_charp message) {
  auto* errors = static_cast<PngErrors*>(png_get_error_ptr(png));
  std::strncpy(errors->message, message, sizeof errors->message - 1);
  png_longjmp(png, 1);
}

void png_ignore_warning(png_structp, png_const_charp) {}

void throw_png_failure(const PngErrors& errors, const std::string& what) {
  if (errors.failure) std::rethrow_exception(errors.failure);
  throw ImageError(what + errors.message);
}

}  // namespace clrt::image_detail

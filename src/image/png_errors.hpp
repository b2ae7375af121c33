// libpng reports errors by longjmp back to a setjmp point. Every libpng call runs inside
// png_guarded(), and the callable given to it must neither throw nor own an object with a
// destructor, since the jump skips destructors: C++ work (allocations, exceptions from the
// output) happens outside, and callbacks catch what they call and turn it into png_error().
#pragma once

#include <png.h>

#include <csetjmp>
#include <exception>
#include <string>

namespace clrt::image_detail {

// The error pointer libpng passes to png_record_error: the message, and an exception a callback
// caught.
struct PngErrors {
  char message[256] = "";
  std::exception_ptr failure;
};

// libpng's error and warning functions: the error's text goes to the PngErrors given to
// png_create_*_struct, then control jumps back to png_guarded; warnings are dropped.
void png_record_error(png_structp png, png_const_charp message);
void png_ignore_warning(png_structp png, png_const_charp message);

// Runs `calls`; false when libpng reported an error on the way.
template <typename Calls>
bool png_guarded(png_structp png, const Calls& calls) {
  if (setjmp(png_jmpbuf(png))) return false;
  calls();
  return true;
}

// After png_guarded failed: rethrows the callback's exception, or throws ImageError(`what` +
// libpng's message).
[[noreturn]] void throw_png_failure(const PngErrors& errors, const std::string& what);

}  // namespace clrt::image_detail

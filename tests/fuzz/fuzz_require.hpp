// How a fuzz path reports a broken promise: std::logic_error, which the targets let escape.
#pragma once

#include <stdexcept>

namespace clrt::fuzz {

inline void require(bool promise, const char* what) {
  if (!promise) throw std::logic_error(what);
}

}  // namespace clrt::fuzz

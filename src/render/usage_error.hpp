// A request that cannot be rendered as asked, found before any work: the command line's or the
// scene's fault, not the machine's (clrt exits 2).
#pragma once

#include <stdexcept>

namespace clrt {

class UsageError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

}  // namespace clrt

// A failed allocation reported by what clrt was doing when it failed, rather than as a bare
// "std::bad_alloc".
#pragma once

#include <new>
#include <stdexcept>
#include <string>

namespace clrt {

class OutOfMemory : public std::runtime_error {
 public:
  explicit OutOfMemory(const std::string& doing) : std::runtime_error("out of memory while " + doing) {}
};

// What `work` returns; a std::bad_alloc it throws becomes OutOfMemory(doing).
template <class Work>
auto naming_out_of_memory(const std::string& doing, Work&& work) {
  try {
    return work();
  } catch (const std::bad_alloc&) {
    throw OutOfMemory(doing);
  }
}

}  // namespace clrt

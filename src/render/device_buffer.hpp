// One device buffer as the checks before a render see it: the name its allocation gives in
// errors and its size.
#pragma once

#include <cstdint>
#include <string>

namespace clrt {

struct DeviceBuffer {
  std::string what;
  std::uint64_t bytes;
};

// X-macro helpers for a class whose buffers are one list X(member, element type, length, name):
// the list declares the members, allocates them and describes them, so the three cannot drift.
#define CLRT_BUFFER_MEMBER(member, type, length, what) Global<type> member;
#define CLRT_BUFFER_ALLOCATE(member, type, length, what) \
  member = allocate<type>(device, static_cast<std::size_t>(length), what);
#define CLRT_BUFFER_DESCRIBE(member, type, length, what) \
  {what, sizeof(type) * static_cast<std::uint64_t>(length)},

}  // namespace clrt

/* Definitions that let one header describe a structure for both the OpenCL C kernels and the
 * C++ host. Every shared structure is built from 4-byte scalars and 16-byte f4 vectors only,
 * so both compilers lay it out identically without hidden padding; tests/kernels/
 * test_layout.cpp checks the sizes and offsets the device sees against the host's. */
#ifndef CLRT_SHARED_COMMON_H
#define CLRT_SHARED_COMMON_H

#ifdef __OPENCL_VERSION__
typedef float4 f4;
typedef uint u32;
typedef int i32;
#define CLRT_SHARED_BEGIN
#define CLRT_SHARED_END
#define CLRT_CHECK_SIZE(type, bytes)
#else
#include <cstdint>
#define CLRT_SHARED_BEGIN namespace clrt { namespace dev {
#define CLRT_SHARED_END } }
#define CLRT_CHECK_SIZE(type, bytes) static_assert(sizeof(type) == (bytes), #type " layout changed")
CLRT_SHARED_BEGIN
/* Matches OpenCL C's float4: four floats, 16-byte aligned. */
struct alignas(16) f4 {
  float x, y, z, w;
};
typedef std::uint32_t u32;
typedef std::int32_t i32;
CLRT_SHARED_END
#endif

#endif

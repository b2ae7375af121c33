/* Definitions that let one header describe a structure for both the OpenCL C kernels and the
 * C++ host. Every shared structure is built from 4-byte scalars and 16-byte f4 vectors only,
 * so both compilers lay it out identically without hidden padding; tests/kernels/
 * test_layout.cpp checks the sizes and offsets the device sees against the host's. */
#ifndef CLRT_SHARED_COMMON_H
#define CLRT_SHARED_COMMON_H

#ifdef __OPENCL_VERSION__
/* No compiler may fuse a*b+c on its own: the same sum gives the same bits in every kernel and on
 * every device (kernels/math/exact.h). */
#pragma OPENCL FP_CONTRACT OFF
typedef float4 f4;
typedef uint u32;
typedef int i32;
#define CLRT_SHARED_BEGIN
#define CLRT_SHARED_END
#define CLRT_CHECK_SIZE(type, bytes)
/* How values cross calls between device functions. Intel's CPU runtime, vectorising a
 * work-group 16 wide, passed the lanes' float3 arguments 12 bytes apart and read them 16 apart
 * in a function it kept out of line (docs/devices.md, tests/device/test_vector_calls.cpp). So a
 * device function is either forced inline, and no value crosses a call at run time, or it is
 * CLRT_CALLABLE: the compiler may keep it a call, and no 3-component vector is among its
 * parameters or its result. tests/device/test_kernel_source.cpp holds every function to it. */
#ifdef CLRT_NO_FORCED_INLINE
/* Oclgrind's interpreter has no llvm.experimental.noalias.scope.decl, which LLVM's inliner
 * emits when it inlines a function returning a structure; it does not vectorise either. */
#define CLRT_INLINE inline
#else
/* Static, so that the front end drops each function once it is inlined everywhere: PoCL (which
 * defines `inline` away) otherwise kept every one, its callees inlined, beside the kernels, and
 * read that bitcode (817 KB for the renderer's program, 292 KB without them) on every warm
 * build (docs/performance.md#what-limits-the-warm-start). */
#define CLRT_INLINE static inline __attribute__((always_inline))
#endif
#define CLRT_CALLABLE inline
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

// How clrt's processes ask the C library to manage the heap.
#pragma once

namespace clrt {

// glibc serves blocks below its mmap threshold from the heap, and raises the threshold (up to
// 32 MiB) each time a larger block is freed: after that, the loader's and the BVH builder's
// tables of a few MB come from the heap and stay resident once freed, in every thread's arena.
// A fixed threshold of 128 KiB gives each such block back when it is freed: 54 MB less at the
// peak of a 1M-triangle scene, for fresh pages on every large block (up to about 10% more CPU
// time in the load and the BVH build). Call first thing in main.
void return_large_blocks_when_freed();

}  // namespace clrt

// How clrt's processes ask the C library to manage the heap.
#pragma once

namespace clrt {

// glibc serves blocks below its mmap threshold from the heap, and raises the threshold (up to
// 32 MiB) each time a larger block is freed: after that, the loader's and the BVH builder's
// tables of a few MB come from the heap and stay resident once freed, in every thread's arena.
// A fixed threshold of 1 MiB gives each such block back when it is freed: 53 MB less at the
// peak of a 1M-triangle scene, for fresh pages on every block above it. 128 KiB saved 1 MB
// more but made the PNG writer's per-band buffers fresh pages too (its write of 1920x1080 went
// from 9-11 to 14-17 ms). Call first thing in main.
void return_large_blocks_when_freed();

}  // namespace clrt

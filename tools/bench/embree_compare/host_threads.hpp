// Host-side tracing on several threads, timed by the wall clock.
#pragma once

#include <cstddef>
#include <functional>

namespace clrt::compare {

// Calls work(begin, end) over blocks of [0, count) on `threads` threads that take the next
// block from a shared counter (so no thread idles while another has a costly half of the
// image); returns the wall time.
// Embree's advice for every thread that traces: denormals flushed to zero.
void flush_denormals();

double parallel_seconds(std::size_t count, int threads,
                        const std::function<void(std::size_t, std::size_t)>& work);

}  // namespace clrt::compare

// Work spread over every core: slices of a mesh file, the bottom levels of many meshes, the
// world boxes of many instances, the large ranges of a BVH build. (Header-only; here because
// every area links clrt_math.)
#pragma once

#include <algorithm>
#include <atomic>
#include <cstddef>
#include <exception>
#include <mutex>
#include <thread>
#include <vector>

namespace clrt {

// Threads parallel_for uses; 0: one per core. Tests and benchmarks set it to show that results
// do not depend on it, and to measure one core.
inline std::atomic<unsigned> parallel_thread_limit{0};

inline unsigned parallel_threads() {
  const unsigned limit = parallel_thread_limit.load();
  return limit ? limit : std::max(1u, std::thread::hardware_concurrency());
}

// Calls work(i) for every i in [0, count), taking `chunk` consecutive indices at a time, on
// parallel_threads() threads. work must be safe to call for different i at once. The first
// exception work throws (std::bad_alloc, a parse error) is thrown here once every thread has
// stopped; the indices not yet taken are then left undone. Where no more threads can start (a
// process at its memory or thread limit) the work runs on the threads there are.
template <class Work>
void parallel_for(std::size_t count, std::size_t chunk, const Work& work) {
  std::atomic<std::size_t> next{0};
  std::exception_ptr failure;
  std::mutex failure_mutex;
  const auto run = [&] {
    try {
      for (std::size_t begin = next.fetch_add(chunk); begin < count; begin = next.fetch_add(chunk))
        for (std::size_t i = begin; i < std::min(count, begin + chunk); ++i) work(i);
    } catch (...) {
      next = count;
      const std::lock_guard<std::mutex> lock(failure_mutex);
      if (!failure) failure = std::current_exception();
    }
  };
  const std::size_t threads_wanted = std::min<std::size_t>(parallel_threads(), (count + chunk - 1) / chunk);
  std::vector<std::thread> threads;
  try {
    threads.reserve(threads_wanted);
    for (std::size_t t = 1; t < threads_wanted; ++t) threads.emplace_back(run);
  } catch (const std::exception&) {
    // No thread more could start: those that did, and this one, take every index.
  }
  run();
  for (std::thread& t : threads) t.join();
  if (failure) std::rethrow_exception(failure);
}

}  // namespace clrt

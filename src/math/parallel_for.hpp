// Work spread over every core: slices of a mesh file, the bottom levels of many meshes, the
// world boxes of many instances. (Header-only; here because every area links clrt_math.)
#pragma once

#include <algorithm>
#include <atomic>
#include <cstddef>
#include <thread>
#include <vector>

namespace clrt {

// Calls work(i) for every i in [0, count), taking `chunk` consecutive indices at a time, on every
// core. work must be safe to call for different i at once.
template <class Work>
void parallel_for(std::size_t count, std::size_t chunk, const Work& work) {
  std::atomic<std::size_t> next{0};
  const auto run = [&] {
    for (std::size_t begin = next.fetch_add(chunk); begin < count; begin = next.fetch_add(chunk))
      for (std::size_t i = begin; i < std::min(count, begin + chunk); ++i) work(i);
  };
  const std::size_t cores = std::max(1u, std::thread::hardware_concurrency());
  std::vector<std::thread> threads;
  for (std::size_t t = 1; t < std::min(cores, (count + chunk - 1) / chunk); ++t) threads.emplace_back(run);
  run();
  for (std::thread& t : threads) t.join();
}

}  // namespace clrt

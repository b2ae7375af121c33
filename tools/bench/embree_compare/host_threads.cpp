#include "host_threads.hpp"

#include <pmmintrin.h>
#include <xmmintrin.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <thread>
#include <vector>

namespace clrt::compare {
namespace {

// Small enough to balance two threads on a 64k-ray set, large enough that the shared counter
// is touched once per ~50 us of tracing.
constexpr std::size_t kBlock = 1024;

}  // namespace

void flush_denormals() {
  _MM_SET_FLUSH_ZERO_MODE(_MM_FLUSH_ZERO_ON);
  _MM_SET_DENORMALS_ZERO_MODE(_MM_DENORMALS_ZERO_ON);
}

double parallel_seconds(std::size_t count, int threads,
                        const std::function<void(std::size_t, std::size_t)>& work) {
  std::atomic<std::size_t> next{0};
  const auto worker = [&] {
    for (std::size_t begin; (begin = next.fetch_add(kBlock)) < count;)
      work(begin, std::min(count, begin + kBlock));
  };
  const auto start = std::chrono::steady_clock::now();
  std::vector<std::thread> pool;
  for (int t = 0; t < threads; ++t) pool.emplace_back(worker);
  for (std::thread& t : pool) t.join();
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace clrt::compare

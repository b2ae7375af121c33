// parallel_for gives a worker's exception to its caller, instead of ending the process
// (an exception that leaves a std::thread calls std::terminate).
#include <catch2/catch.hpp>

#include <atomic>
#include <new>
#include <stdexcept>

#include "math/parallel_for.hpp"

using clrt::parallel_for;

TEST_CASE("parallel_for does every index once", "[math][parallel]") {
  std::vector<std::atomic<int>> done(1000);
  parallel_for(done.size(), 7, [&](std::size_t i) { ++done[i]; });
  for (const auto& d : done) CHECK(d == 1);
}

TEST_CASE("an exception in any thread of parallel_for reaches the caller", "[math][parallel]") {
  for (unsigned threads : {1u, 2u, 4u}) {
    clrt::parallel_thread_limit = threads;
    CHECK_THROWS_AS(parallel_for(64, 1, [](std::size_t i) {
                      if (i == 37) throw std::bad_alloc();
                    }),
                    std::bad_alloc);
    CHECK_THROWS_WITH(parallel_for(64, 1, [](std::size_t i) {
                        if (i % 2) throw std::runtime_error("slice " + std::to_string(i % 2));
                      }),
                      "slice 1");
  }
  clrt::parallel_thread_limit = 0;
}

#include "rank_test.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <utility>

namespace clrt::experiment {
namespace {

// The rank of each pooled value (1-based, ties sharing their mean rank), `a`'s first.
std::vector<double> pooled_ranks(const std::vector<double>& a, const std::vector<double>& b) {
  std::vector<std::pair<double, std::size_t>> pooled;
  for (std::size_t i = 0; i < a.size(); ++i) pooled.push_back({a[i], i});
  for (std::size_t i = 0; i < b.size(); ++i) pooled.push_back({b[i], a.size() + i});
  std::sort(pooled.begin(), pooled.end());
  std::vector<double> rank(pooled.size());
  for (std::size_t i = 0; i < pooled.size();) {
    std::size_t j = i;
    while (j < pooled.size() && pooled[j].first == pooled[i].first) ++j;
    const double mean_rank = 0.5 * static_cast<double>(i + 1 + j);
    for (std::size_t k = i; k < j; ++k) rank[pooled[k].second] = mean_rank;
    i = j;
  }
  return rank;
}

double binomial(int n, int k) {
  double c = 1;
  for (int i = 1; i <= k; ++i) c = c * (n - k + i) / i;
  return c;
}

}  // namespace

double mann_whitney_p(const std::vector<double>& a, const std::vector<double>& b) {
  const std::size_t n = a.size(), m = b.size(), all = n + m;
  if (n == 0 || m == 0) return 1;
  const std::vector<double> rank = pooled_ranks(a, b);
  double observed = 0;
  for (std::size_t i = 0; i < n; ++i) observed += rank[i];
  const double mean = 0.5 * static_cast<double>(n * (all + 1));
  const double distance = std::fabs(observed - mean) - 1e-9;
  if (all <= 20) {
    // Every way of giving n of the pooled ranks to `a`, as a bit mask over them.
    std::uint64_t at_least = 0, splits = 0;
    for (std::uint32_t mask = 0; mask < (1u << all); ++mask) {
      if (static_cast<std::size_t>(__builtin_popcount(mask)) != n) continue;
      double sum = 0;
      for (std::size_t i = 0; i < all; ++i)
        if (mask & (1u << i)) sum += rank[i];
      ++splits;
      if (std::fabs(sum - mean) >= distance) ++at_least;
    }
    return static_cast<double>(at_least) / static_cast<double>(splits);
  }
  const double sd = std::sqrt(static_cast<double>(n * m * (all + 1)) / 12.0);
  return std::erfc(std::max(0.0, distance) / (sd * std::sqrt(2.0)));
}

double smallest_mann_whitney_p(int n, int m) {
  return n > 0 && m > 0 ? std::min(1.0, 2.0 / binomial(n + m, n)) : 1.0;
}

}  // namespace clrt::experiment

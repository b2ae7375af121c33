#include "math/cumulative_shares.hpp"

namespace clrt {

std::vector<float> cumulative_shares(const std::vector<double>& weights) {
  double total = 0;
  for (double w : weights) total += w;
  const bool even = !(total > 0);
  if (even) total = static_cast<double>(weights.size());
  std::vector<float> shares(weights.size());
  double running = 0;
  for (std::size_t i = 0; i < weights.size(); ++i) {
    running += even ? 1.0 : weights[i];
    shares[i] = i + 1 == weights.size() ? 1.0f : static_cast<float>(running / total);
  }
  return shares;
}

}  // namespace clrt

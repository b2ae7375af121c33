#include "math/stratification_grid.hpp"

namespace clrt {

Grid stratification_grid(unsigned n) {
  unsigned v = 1;
  for (unsigned d = 1; static_cast<unsigned long long>(d) * d <= n; ++d)
    if (n % d == 0) v = d;
  return {n / v, v};
}

}  // namespace clrt

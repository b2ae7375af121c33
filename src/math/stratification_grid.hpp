// The contract's stratification of n samples into a grid: v is the largest divisor of n not
// above sqrt(n), u = n / v. Camera samples and an area light's samples both use it.
#pragma once

namespace clrt {

struct Grid {
  unsigned u = 1, v = 1;
};
Grid stratification_grid(unsigned n);

}  // namespace clrt

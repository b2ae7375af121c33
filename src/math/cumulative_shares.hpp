// Tables of cumulative shares, which the device searches to draw an entry in proportion to its
// weight (kernels/math/cumulative_pick.h): the glow light's rows, the environment's rows and
// texels.
#pragma once

#include <vector>

namespace clrt {

// The running sums of `weights` over their total, in single precision, the last exactly 1 so
// that every number below 1 finds an entry; equal shares when the weights sum to 0.
std::vector<float> cumulative_shares(const std::vector<double>& weights);

}  // namespace clrt

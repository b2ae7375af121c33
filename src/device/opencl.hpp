// The one place that includes Boost.Compute, so every file sees the same configuration.
#pragma once

#pragma GCC system_header
#include <boost/compute/core.hpp>

namespace clrt {
namespace compute = boost::compute;

// Something went wrong on the OpenCL side: no device, a build failure, a refused allocation.
class DeviceError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

}  // namespace clrt

#include <cstddef>

#include "device/kernel_args.hpp"

namespace clrt {
namespace {

std::string arg_string(const compute::kernel& kernel, cl_uint index, cl_kernel_arg_info what,
                       cl_int& error) {
  std::size_t size = 0;
  error = clGetKernelArgInfo(kernel.get(), index, what, 0, nullptr, &size);
  if (error != CL_SUCCESS) return {};
  std::string value(size, '\0');
  error = clGetKernelArgInfo(kernel.get(), index, what, size, value.data(), nullptr);
  while (!value.empty() && value.back() == '\0') value.pop_back();
  return value;
}

template <class T>
T arg_value(const compute::kernel& kernel, cl_uint index, cl_kernel_arg_info what) {
  T value{};
  clGetKernelArgInfo(kernel.get(), index, what, sizeof value, &value, nullptr);
  return value;
}

}  // namespace

std::vector<std::string> signature_mismatches(const compute::kernel& kernel,
                                              const std::vector<ExpectedArg>& expected) {
  std::vector<std::string> out;
  const std::string name = kernel.name();
  const auto count = kernel.get_info<cl_uint>(CL_KERNEL_NUM_ARGS);
  if (count != expected.size())
    out.push_back(name + ": the kernel takes " + std::to_string(count) +
                  " arguments, the host structure has " + std::to_string(expected.size()));
  for (cl_uint i = 0; i < count && i < expected.size(); ++i) {
    const ExpectedArg& e = expected[i];
    cl_int error = CL_SUCCESS;
    const std::string arg_name = arg_string(kernel, i, CL_KERNEL_ARG_NAME, error);
    if (error != CL_SUCCESS) {
      out.push_back(name + ": the device reports no argument information (error " +
                    std::to_string(error) + ")");
      return out;
    }
    const std::string type = arg_string(kernel, i, CL_KERNEL_ARG_TYPE_NAME, error);
    const auto address = arg_value<cl_kernel_arg_address_qualifier>(kernel, i,
                                                                    CL_KERNEL_ARG_ADDRESS_QUALIFIER);
    const auto qualifiers = arg_value<cl_kernel_arg_type_qualifier>(kernel, i,
                                                                   CL_KERNEL_ARG_TYPE_QUALIFIER);
    const std::string where = name + " argument " + std::to_string(i) + " ";
    if (arg_name != e.name) out.push_back(where + "is '" + arg_name + "', the host binds '" + e.name + "'");
    if (type != e.type_name)
      out.push_back(where + "'" + arg_name + "' has type " + type + ", the host binds " + e.type_name);
    if ((address == CL_KERNEL_ARG_ADDRESS_GLOBAL) != e.global)
      out.push_back(where + "'" + arg_name + "': " +
                    (e.global ? "the host binds a __global buffer" : "the host binds a value"));
    const bool is_const = (qualifiers & CL_KERNEL_ARG_TYPE_CONST) != 0;
    if (e.global && is_const != e.is_const)
      out.push_back(where + "'" + arg_name + "': " +
                    (e.is_const ? "the host expects const" : "the host writes to it, the kernel has it const"));
  }
  return out;
}

}  // namespace clrt

#include <cstddef>
#include <map>
#include <mutex>
#include <sstream>

#include "device/kernel_args.hpp"

namespace clrt {
namespace {

// One parameter as the device reports it.
struct ArgRecord {
  std::string name, type;
  cl_kernel_arg_address_qualifier address = 0;
  cl_kernel_arg_type_qualifier qualifiers = 0;
};
using KernelRecords = std::map<std::string, std::vector<ArgRecord>>;

std::string arg_string(cl_kernel kernel, cl_uint index, cl_kernel_arg_info what, cl_int& error) {
  std::size_t size = 0;
  error = clGetKernelArgInfo(kernel, index, what, 0, nullptr, &size);
  if (error != CL_SUCCESS) return {};
  std::string value(size, '\0');
  error = clGetKernelArgInfo(kernel, index, what, size, value.data(), nullptr);
  while (!value.empty() && value.back() == '\0') value.pop_back();
  return value;
}

template <class T>
T arg_value(cl_kernel kernel, cl_uint index, cl_kernel_arg_info what) {
  T value{};
  clGetKernelArgInfo(kernel, index, what, sizeof value, &value, nullptr);
  return value;
}

// The parameters the driver reports, or the error that says it has no argument information.
std::vector<ArgRecord> driver_args(cl_kernel kernel, cl_uint count, cl_int& error) {
  std::vector<ArgRecord> out;
  for (cl_uint i = 0; i < count; ++i) {
    ArgRecord a;
    a.name = arg_string(kernel, i, CL_KERNEL_ARG_NAME, error);
    if (error != CL_SUCCESS) return {};
    a.type = arg_string(kernel, i, CL_KERNEL_ARG_TYPE_NAME, error);
    if (error != CL_SUCCESS) return {};
    a.address = arg_value<cl_kernel_arg_address_qualifier>(kernel, i, CL_KERNEL_ARG_ADDRESS_QUALIFIER);
    a.qualifiers = arg_value<cl_kernel_arg_type_qualifier>(kernel, i, CL_KERNEL_ARG_TYPE_QUALIFIER);
    out.push_back(a);
  }
  return out;
}

// Records adopted from the program cache, for programs made from a binary: some drivers
// (Intel's CPU runtime) keep no argument information in a binary. Each program is retained
// while it is listed, so its handle cannot be reused for another.
std::mutex registry_mutex;
std::map<cl_program, KernelRecords>& registry() {
  static std::map<cl_program, KernelRecords> programs;
  return programs;
}

const std::vector<ArgRecord>* adopted_args(cl_kernel kernel, const std::string& name) {
  cl_program program = nullptr;
  if (clGetKernelInfo(kernel, CL_KERNEL_PROGRAM, sizeof program, &program, nullptr) != CL_SUCCESS)
    return nullptr;
  const std::lock_guard<std::mutex> lock(registry_mutex);
  const auto p = registry().find(program);
  if (p == registry().end()) return nullptr;
  const auto k = p->second.find(name);
  return k == p->second.end() ? nullptr : &k->second;
}

}  // namespace

std::string program_signatures(const compute::program& program) {
  cl_uint count = 0;
  if (clCreateKernelsInProgram(program.get(), 0, nullptr, &count) != CL_SUCCESS) return {};
  std::vector<cl_kernel> kernels(count);
  if (clCreateKernelsInProgram(program.get(), count, kernels.data(), nullptr) != CL_SUCCESS) return {};
  std::ostringstream out;
  bool complete = true;
  for (cl_kernel k : kernels) {
    const compute::kernel kernel(k, false);  // takes over the reference
    const auto args = kernel.get_info<cl_uint>(CL_KERNEL_NUM_ARGS);
    cl_int error = CL_SUCCESS;
    const std::vector<ArgRecord> records = driver_args(k, args, error);
    if (error != CL_SUCCESS) complete = false;
    for (std::size_t i = 0; i < records.size(); ++i)
      out << kernel.name() << '\t' << i << '\t' << records[i].name << '\t' << records[i].type << '\t'
          << records[i].address << '\t' << records[i].qualifiers << '\n';
  }
  return complete ? out.str() : std::string();
}

void adopt_signatures(const compute::program& program, const std::string& text) {
  KernelRecords records;
  std::istringstream in(text);
  std::string line;
  while (std::getline(in, line)) {
    std::istringstream fields(line);
    std::string kernel, index;
    ArgRecord a;
    if (std::getline(fields, kernel, '\t') && std::getline(fields, index, '\t') &&
        std::getline(fields, a.name, '\t') && std::getline(fields, a.type, '\t') &&
        fields >> a.address >> a.qualifiers)
      records[kernel].push_back(a);
  }
  const std::lock_guard<std::mutex> lock(registry_mutex);
  if (registry().emplace(program.get(), std::move(records)).second) clRetainProgram(program.get());
}

std::vector<std::string> signature_mismatches(const compute::kernel& kernel,
                                              const std::vector<ExpectedArg>& expected) {
  std::vector<std::string> out;
  const std::string name = kernel.name();
  const auto count = kernel.get_info<cl_uint>(CL_KERNEL_NUM_ARGS);
  if (count != expected.size())
    out.push_back(name + ": the kernel takes " + std::to_string(count) +
                  " arguments, the host structure has " + std::to_string(expected.size()));
  cl_int error = CL_SUCCESS;
  std::vector<ArgRecord> args = driver_args(kernel.get(), count, error);
  if (error != CL_SUCCESS) {
    const std::vector<ArgRecord>* adopted = adopted_args(kernel.get(), name);
    if (adopted == nullptr || adopted->size() != count) {
      out.push_back(name + ": the device reports no argument information (error " +
                    std::to_string(error) + ")");
      return out;
    }
    args = *adopted;
  }
  for (cl_uint i = 0; i < count && i < expected.size(); ++i) {
    const ExpectedArg& e = expected[i];
    const ArgRecord& a = args[i];
    const std::string where = name + " argument " + std::to_string(i) + " ";
    if (a.name != e.name) out.push_back(where + "is '" + a.name + "', the host binds '" + e.name + "'");
    if (a.type != e.type_name)
      out.push_back(where + "'" + a.name + "' has type " + a.type + ", the host binds " + e.type_name);
    if ((a.address == CL_KERNEL_ARG_ADDRESS_GLOBAL) != e.global)
      out.push_back(where + "'" + a.name + "': " +
                    (e.global ? "the host binds a __global buffer" : "the host binds a value"));
    const bool is_const = (a.qualifiers & CL_KERNEL_ARG_TYPE_CONST) != 0;
    if (e.global && is_const != e.is_const)
      out.push_back(where + "'" + a.name + "': " +
                    (e.is_const ? "the host expects const" : "the host writes to it, the kernel has it const"));
  }
  return out;
}

}  // namespace clrt

// Typed kernel arguments. Each kernel's arguments are one host structure whose fields carry the
// kernel's parameter names; CLRT_KERNEL_ARGS(field, ...) lists them once, in the kernel's order,
// and is the only place that knows that order (a field that is itself such a structure stands
// for its own fields, e.g. the SCENE_PARAMS every tracing kernel takes). TypedKernel binds a
// structure in one call, and signature_mismatches() checks the structure against the kernel's
// own signature as the device reports it, so a signature change fails loudly instead of binding
// the wrong buffer.
#pragma once

#include <string>
#include <type_traits>
#include <vector>

#include "device/opencl.hpp"
#include "shared/common.h"

namespace clrt {

// A `__global T*` parameter (`__global const T*` when T is const): a buffer that holds Ts.
template <class T>
struct Global {
  compute::buffer buffer;

  Global() = default;
  Global(compute::buffer b) : buffer(std::move(b)) {}  // NOLINT: a buffer is a Global of its type
  // A read-only view of the same buffer.
  operator Global<const T>() const { return Global<const T>(buffer); }
};

// The OpenCL C name of each type that crosses as a kernel argument or a buffer element. The
// layer that owns a record type names it (geometry/device_geometry.hpp, render/stage_args.hpp),
// so this layer knows only the scalars.
template <class T>
struct DeviceTypeName;
template <class T>
struct DeviceTypeName<const T> : DeviceTypeName<T> {};

#define CLRT_DEVICE_TYPE_NAME(host_type, device_name) \
  template <>                                         \
  struct DeviceTypeName<host_type> {                  \
    static constexpr const char* value = device_name; \
  }

CLRT_DEVICE_TYPE_NAME(cl_int, "int");
CLRT_DEVICE_TYPE_NAME(cl_uint, "uint");
CLRT_DEVICE_TYPE_NAME(cl_ulong, "ulong");
CLRT_DEVICE_TYPE_NAME(float, "float");
CLRT_DEVICE_TYPE_NAME(dev::f4, "float4");
CLRT_DEVICE_TYPE_NAME(cl_uint4, "uint4");

// What the host expects of one kernel parameter.
struct ExpectedArg {
  std::string name;       // the parameter's name in the kernel source
  std::string type_name;  // as clGetKernelArgInfo reports it: "uint", "Ray*"
  bool global = false;    // a __global pointer (else a value)
  bool is_const = false;  // a pointer to const
};

namespace detail {

template <class T, class = void>
struct HasVisit : std::false_type {};
template <class T>
struct HasVisit<T, std::void_t<typename T::KernelArgList>> : std::true_type {};

// A nested argument structure visits its own fields; any other field is one argument.
template <class Visit, class T>
void visit_field(Visit& v, const char* name, const T& field) {
  if constexpr (HasVisit<T>::value)
    field.visit(v);
  else
    v(name, field);
}

template <class T>
void describe(std::vector<ExpectedArg>& out, const char* name, const Global<T>&) {
  out.push_back({name, std::string(DeviceTypeName<T>::value) + "*", true, std::is_const_v<T>});
}

template <class T>
void describe(std::vector<ExpectedArg>& out, const char* name, const T&) {
  out.push_back({name, DeviceTypeName<T>::value, false, false});
}

template <class T>
void set(compute::kernel& kernel, cl_uint index, const Global<T>& arg) {
  kernel.set_arg(index, arg.buffer);
}

template <class T>
void set(compute::kernel& kernel, cl_uint index, const T& arg) {
  kernel.set_arg(index, sizeof(T), &arg);
}

}  // namespace detail

#define CLRT_ARGS_1(a) ::clrt::detail::visit_field(v, #a, a);
#define CLRT_ARGS_2(a, ...) CLRT_ARGS_1(a) CLRT_ARGS_1(__VA_ARGS__)
#define CLRT_ARGS_3(a, ...) CLRT_ARGS_1(a) CLRT_ARGS_2(__VA_ARGS__)
#define CLRT_ARGS_4(a, ...) CLRT_ARGS_1(a) CLRT_ARGS_3(__VA_ARGS__)
#define CLRT_ARGS_5(a, ...) CLRT_ARGS_1(a) CLRT_ARGS_4(__VA_ARGS__)
#define CLRT_ARGS_6(a, ...) CLRT_ARGS_1(a) CLRT_ARGS_5(__VA_ARGS__)
#define CLRT_ARGS_7(a, ...) CLRT_ARGS_1(a) CLRT_ARGS_6(__VA_ARGS__)
#define CLRT_ARGS_8(a, ...) CLRT_ARGS_1(a) CLRT_ARGS_7(__VA_ARGS__)
#define CLRT_ARGS_9(a, ...) CLRT_ARGS_1(a) CLRT_ARGS_8(__VA_ARGS__)
#define CLRT_ARGS_10(a, ...) CLRT_ARGS_1(a) CLRT_ARGS_9(__VA_ARGS__)
#define CLRT_ARGS_11(a, ...) CLRT_ARGS_1(a) CLRT_ARGS_10(__VA_ARGS__)
#define CLRT_ARGS_12(a, ...) CLRT_ARGS_1(a) CLRT_ARGS_11(__VA_ARGS__)
#define CLRT_ARGS_13(a, ...) CLRT_ARGS_1(a) CLRT_ARGS_12(__VA_ARGS__)
#define CLRT_ARGS_14(a, ...) CLRT_ARGS_1(a) CLRT_ARGS_13(__VA_ARGS__)
#define CLRT_ARGS_COUNT(...) \
  CLRT_ARGS_COUNT_(__VA_ARGS__, 14, 13, 12, 11, 10, 9, 8, 7, 6, 5, 4, 3, 2, 1, 0)
#define CLRT_ARGS_COUNT_(a1, a2, a3, a4, a5, a6, a7, a8, a9, a10, a11, a12, a13, a14, n, ...) n
#define CLRT_ARGS_CAT(a, b) CLRT_ARGS_CAT_(a, b)
#define CLRT_ARGS_CAT_(a, b) a##b

// Inside an argument structure: the kernel's parameters, in order, by field name.
#define CLRT_KERNEL_ARGS(...)                                          \
  using KernelArgList = void;                                          \
  template <class Visit>                                               \
  void visit(Visit&& v) const {                                        \
    CLRT_ARGS_CAT(CLRT_ARGS_, CLRT_ARGS_COUNT(__VA_ARGS__))(__VA_ARGS__) \
  }

// The parameters an argument structure lists, in order.
template <class Args>
std::vector<ExpectedArg> expected_args(const Args& args) {
  std::vector<ExpectedArg> out;
  args.visit([&](const char* name, const auto& field) { detail::describe(out, name, field); });
  return out;
}

// Sets every argument of `kernel` from `args`.
template <class Args>
void bind_args(compute::kernel& kernel, const Args& args) {
  cl_uint index = 0;
  args.visit([&](const char*, const auto& field) { detail::set(kernel, index++, field); });
}

// Every way `kernel`'s signature, as the device reports it, differs from `expected` (empty
// when they agree). The program must have been built with -cl-kernel-arg-info. A program made
// from a cached binary, on a driver that keeps no argument information in binaries, is checked
// against what the driver reported when it built the program from source (adopt_signatures);
// with neither, one line says so.
std::vector<std::string> signature_mismatches(const compute::kernel& kernel,
                                              const std::vector<ExpectedArg>& expected);

// Every kernel's parameters as the driver reports them for `program`, as text; empty when the
// driver reports none.
std::string program_signatures(const compute::program& program);
// Makes `text` (program_signatures of the program built from source) the record that binding
// checks of `program` fall back on.
void adopt_signatures(const compute::program& program, const std::string& text);

}  // namespace clrt

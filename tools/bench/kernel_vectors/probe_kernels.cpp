// Builds a file of probe kernels (probes.cl) on PoCL's CPU device and launches each of them once,
// so that PoCL compiles each into its cache, where kernel_vectors.py --probes reads the code.
// Usage: clrt-kernel-probes PROBES.cl
#define CL_TARGET_OPENCL_VERSION 120
#include <CL/cl.h>

#include <fstream>
#include <iostream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace {

constexpr size_t kItems = 1 << 14, kLocalSize = 64;

void check(cl_int status, const char* what) {
  if (status != CL_SUCCESS) throw std::runtime_error(std::string(what) + " failed (" + std::to_string(status) + ")");
}

cl_device_id pocl_cpu() {
  cl_uint count = 0;
  check(clGetPlatformIDs(0, nullptr, &count), "clGetPlatformIDs");
  std::vector<cl_platform_id> platforms(count);
  check(clGetPlatformIDs(count, platforms.data(), nullptr), "clGetPlatformIDs");
  for (cl_platform_id p : platforms) {
    char name[256] = {};
    clGetPlatformInfo(p, CL_PLATFORM_NAME, sizeof name, name, nullptr);
    cl_device_id device = nullptr;
    if (std::string(name) == "Portable Computing Language" &&
        clGetDeviceIDs(p, CL_DEVICE_TYPE_CPU, 1, &device, nullptr) == CL_SUCCESS)
      return device;
  }
  throw std::runtime_error("no PoCL CPU device");
}

// Every probe takes (in4, in, out, count): bound here, once.
void bind_probe_arguments(cl_kernel kernel, cl_mem in4, cl_mem in, cl_mem out) {
  const cl_uint count = kItems;
  check(clSetKernelArg(kernel, 0, sizeof in4, &in4), "binding in4");
  check(clSetKernelArg(kernel, 1, sizeof in, &in), "binding in");
  check(clSetKernelArg(kernel, 2, sizeof out, &out), "binding out");
  check(clSetKernelArg(kernel, 3, sizeof count, &count), "binding count");
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 2) {
    std::cerr << "usage: clrt-kernel-probes PROBES.cl\n";
    return 2;
  }
  try {
    std::ifstream file(argv[1]);
    if (!file) throw std::runtime_error(std::string("cannot read ") + argv[1]);
    std::stringstream text;
    text << file.rdbuf();
    const std::string source = text.str();
    const char* sources[] = {source.c_str()};
    cl_int status = CL_SUCCESS;
    cl_device_id device = pocl_cpu();
    cl_context context = clCreateContext(nullptr, 1, &device, nullptr, nullptr, &status);
    check(status, "clCreateContext");
    cl_command_queue queue = clCreateCommandQueue(context, device, 0, &status);
    check(status, "clCreateCommandQueue");
    cl_program program = clCreateProgramWithSource(context, 1, sources, nullptr, &status);
    check(status, "clCreateProgramWithSource");
    // The options clrt builds its own kernels with on PoCL (src/device/device_context.cpp).
    check(clBuildProgram(program, 1, &device, "-cl-std=CL1.2 -cl-fp32-correctly-rounded-divide-sqrt",
                         nullptr, nullptr),
          "building the probes");
    const std::vector<float> ones(4 * kItems, 1.0f);
    const auto buffer = [&](cl_mem_flags flags) {
      cl_mem b = clCreateBuffer(context, flags | CL_MEM_COPY_HOST_PTR, sizeof(float) * ones.size(),
                                const_cast<float*>(ones.data()), &status);
      check(status, "clCreateBuffer");
      return b;
    };
    cl_mem in4 = buffer(CL_MEM_READ_ONLY), in = buffer(CL_MEM_READ_ONLY), out = buffer(CL_MEM_READ_WRITE);
    cl_uint kernels = 0;
    check(clCreateKernelsInProgram(program, 0, nullptr, &kernels), "clCreateKernelsInProgram");
    std::vector<cl_kernel> all(kernels);
    check(clCreateKernelsInProgram(program, kernels, all.data(), nullptr), "clCreateKernelsInProgram");
    for (cl_kernel kernel : all) {
      bind_probe_arguments(kernel, in4, in, out);
      check(clEnqueueNDRangeKernel(queue, kernel, 1, nullptr, &kItems, &kLocalSize, 0, nullptr, nullptr),
            "launching a probe");
    }
    check(clFinish(queue), "clFinish");
    for (cl_kernel kernel : all) clReleaseKernel(kernel);
    for (cl_mem b : {in4, in, out}) clReleaseMemObject(b);
    clReleaseProgram(program);
    clReleaseCommandQueue(queue);
    clReleaseContext(context);
  } catch (const std::exception& e) {
    std::cerr << "clrt-kernel-probes: " << e.what() << "\n";
    return 1;
  }
  return 0;
}

// Starting OpenCL (the ICD loader opening PoCL: about 25 ms) and building the program (about
// 30 ms from a warm kernel cache) need nothing from the scene, so they run on a thread of their
// own while the scene loads and its BVH builds, and leave the command's critical path.
#pragma once

#include <future>
#include <memory>
#include <string>
#include <vector>

#include "device/device_context.hpp"
#include "device/device_select.hpp"

namespace clrt {

// A device with its context and the renderer's program built on it.
struct PreparedDevice {
  std::unique_ptr<DeviceContext> context;
  compute::program program;
};

class DevicePreparation {
 public:
  // Starts choosing the devices `spec` names (as --device) and building the program on each.
  explicit DevicePreparation(const std::string& spec);
  ~DevicePreparation();
  DevicePreparation(const DevicePreparation&) = delete;
  DevicePreparation& operator=(const DevicePreparation&) = delete;

  // The devices chosen; rethrows the choice's error (DeviceError: no such device).
  const std::vector<DeviceEntry>& devices();
  // The contexts and programs, once; rethrows a build's error.
  std::vector<PreparedDevice> take();

 private:
  std::shared_future<std::vector<DeviceEntry>> chosen_;
  std::future<std::vector<PreparedDevice>> built_;
};

}  // namespace clrt

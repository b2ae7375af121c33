// Choosing devices, building programs and allocating buffers: the errors users see.
#include <catch2/catch.hpp>

#include <algorithm>

#include "cl_fixture.hpp"
#include "device/device_select.hpp"

using namespace clrt;

TEST_CASE("device specs choose devices", "[device]") {
  const std::vector<DeviceEntry> all = enumerate_devices();
  REQUIRE_FALSE(all.empty());
  const std::vector<DeviceEntry> cpu = select_devices("cpu");
  REQUIRE(cpu.size() == 1);
  CHECK((cpu[0].device.type() & CL_DEVICE_TYPE_CPU) != 0);
  CHECK(select_devices("all").size() == all.size());
  const auto by_index = select_devices(std::to_string(all[0].platform_index) + ":" +
                                       std::to_string(all[0].device_index));
  REQUIRE(by_index.size() == 1);
  CHECK(by_index[0].device.get() == all[0].device.get());
  // Part of the name, in any case.
  std::string part = all[0].device.name().substr(0, 6);
  for (char& c : part) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  CHECK_FALSE(select_devices(part).empty());
}

TEST_CASE("cpu is PoCL's CPU device wherever PoCL is installed, whatever is listed first",
          "[device][default-device]") {
  // Run again with Intel's runtime listed before PoCL (test_device@intel), where the first CPU
  // device is Intel's.
  const std::vector<DeviceEntry> all = enumerate_devices();
  const auto is_pocl = [](const DeviceEntry& e) {
    return e.device.platform().name() == "Portable Computing Language";
  };
  const std::vector<DeviceEntry> cpu = select_devices("cpu");
  REQUIRE(cpu.size() == 1);
  const bool pocl_installed = std::any_of(all.begin(), all.end(), [&](const DeviceEntry& e) {
    return is_pocl(e) && (e.device.type() & CL_DEVICE_TYPE_CPU);
  });
  INFO("the first device: " << all.front().device.platform().name());
  if (pocl_installed) {
    CHECK(is_pocl(cpu[0]));
    // NAME:D names it whatever the platforms' order: PoCL's vendor is "The pocl project".
    const std::vector<DeviceEntry> named = select_devices("pocl:0");
    REQUIRE(named.size() == 1);
    CHECK(is_pocl(named[0]));
    CHECK(named[0].device_index == 0);
    CHECK(select_devices("Portable:0").size() == 1);
  }
}

TEST_CASE("a spec that matches nothing lists the devices that exist", "[device]") {
  const std::string name = enumerate_devices().front().device.name();
  CHECK_THROWS_AS(select_devices("no-such-device"), DeviceError);
  CHECK_THROWS_WITH(select_devices("no-such-device"),
                    Catch::Contains("--device no-such-device") && Catch::Contains(name));
  CHECK_THROWS_WITH(select_devices("7:9"), Catch::Contains("0:0"));
}

TEST_CASE("describe_device names index, device, type, units, memory and OpenCL C", "[device]") {
  const std::string text = describe_device(select_devices("cpu").front());
  CHECK(text.rfind("0:", 0) == 0);
  CHECK(text.find("CPU") != std::string::npos);
  CHECK(text.find("compute units") != std::string::npos);
  CHECK(text.find("MiB") != std::string::npos);
  CHECK(text.find("OpenCL C") != std::string::npos);
}

TEST_CASE("the device line of a render fits 80 columns, naming index, device and platform",
          "[device]") {
  const DeviceEntry entry = select_devices("cpu").front();
  const std::string line = device_line(entry);
  INFO(line);
  CHECK(line.size() <= 80);
  CHECK(line.rfind("device 0:", 0) == 0);
  CHECK(line.find(" units, ") != std::string::npos);
  const std::string name = entry.device.name(), platform = entry.device.platform().name();
  CHECK(line.find(" GiB) on " + platform.substr(0, 9)) != std::string::npos);
  // The name gives way last: it is cut only when it does not fit beside the platform's shortest
  // form (12 characters), as on a machine whose processor has a long name.
  if (line.find(name) == std::string::npos) {
    CHECK(line.size() == 80);
    const std::string shortest = platform.size() <= 12 ? platform : platform.substr(0, 9) + "...";
    CHECK(line.compare(line.size() - shortest.size(), shortest.size(), shortest) == 0);
    CHECK(line.find(name.substr(0, 8)) != std::string::npos);
  }
  const std::string narrow = device_line(entry, 60);
  CHECK(narrow.size() <= 60);
  CHECK(narrow.find("...") != std::string::npos);
}

TEST_CASE("a kernel build failure carries the whole build log with the real file name",
          "[device]") {
  const std::string source = "#line 1 \"kernels/broken.cl\"\n__kernel void f(__global int* x) {\n"
                             "  x[0] = undefined_name;\n}\n";
  try {
    test::device().build(source);
    FAIL("the build should have failed");
  } catch (const DeviceError& e) {
    const std::string message = e.what();
    CHECK(message.find("kernel build failed") != std::string::npos);
    CHECK(message.find("build log") != std::string::npos);
    CHECK(message.find("kernels/broken.cl:2") != std::string::npos);
    CHECK(message.find("undefined_name") != std::string::npos);
  }
}

TEST_CASE("an allocation the device refuses names the buffer and its size", "[device]") {
  const auto max_alloc = test::device().device().get_info<cl_ulong>(CL_DEVICE_MAX_MEM_ALLOC_SIZE);
  try {
    test::device().allocate(static_cast<std::size_t>(max_alloc) + (1u << 20), "giant test");
    FAIL("the allocation should have been refused");
  } catch (const DeviceError& e) {
    const std::string message = e.what();
    CHECK(message.find("giant test buffer") != std::string::npos);
    CHECK(message.find("MiB") != std::string::npos);
    CHECK(message.find("--wavefront") != std::string::npos);
  }
}

// The memory a load may take is the least of what the machine, the process's limits and its
// cgroup leave, each read from files a test can write; the loaders stop before they pass it.
#include <catch2/catch.hpp>

#include <string>

#include "scene/memory_limit.hpp"
#include "scene/mesh_loader.hpp"
#include "scratch_dir.hpp"

using namespace clrt;

namespace {

constexpr std::uint64_t kKiB = 1024;

// A /proc and a /sys/fs/cgroup of the test's own: 1,000,000 kB available, 400,000 kB of
// address space and 300,000 kB of data in use, and the cgroup /box/job.
struct FakeSystem {
  test::ScratchDir dir;
  MemorySources sources;

  FakeSystem() {
    sources.proc = dir.file("proc");
    sources.cgroup_root = dir.file("cgroup");
    dir.write("proc/meminfo", "MemTotal:       4000000 kB\nMemAvailable:   1000000 kB\n");
    dir.write("proc/self/status", "Name: clrt\nVmSize:\t  400000 kB\nVmData:\t  300000 kB\n");
    dir.write("proc/self/cgroup", "0::/box/job\n");
    dir.write("cgroup/box/job/memory.max", "max\n");
    dir.write("cgroup/box/memory.max", "max\n");
  }
};

}  // namespace

TEST_CASE("memory: MemAvailable when nothing else limits the process", "[scene][memory]") {
  FakeSystem system;
  const MemoryLimit limit = memory_limit(system.sources);
  CHECK(limit.bytes == 1000000 * kKiB);
  CHECK(limit.source == "MemAvailable");
}

TEST_CASE("memory: RLIMIT_AS and RLIMIT_DATA less what the process already uses",
          "[scene][memory]") {
  FakeSystem system;
  system.sources.address_space_limit = 900000 * kKiB;
  MemoryLimit limit = memory_limit(system.sources);
  CHECK(limit.bytes == 500000 * kKiB);
  CHECK(limit.source == "RLIMIT_AS, ulimit -v");
  system.sources.data_limit = 500000 * kKiB;
  limit = memory_limit(system.sources);
  CHECK(limit.bytes == 200000 * kKiB);
  CHECK(limit.source == "RLIMIT_DATA, ulimit -d");
  system.sources.data_limit = 100000 * kKiB;  // already past it
  CHECK(memory_limit(system.sources).bytes == 0);
}

TEST_CASE("memory: the cgroup's memory.max less memory.current, at any level above the process",
          "[scene][memory]") {
  FakeSystem system;
  system.dir.write("cgroup/box/memory.max", std::to_string(600000 * kKiB) + "\n");
  system.dir.write("cgroup/box/memory.current", std::to_string(150000 * kKiB) + "\n");
  MemoryLimit limit = memory_limit(system.sources);
  CHECK(limit.bytes == 450000 * kKiB);
  CHECK(limit.source == "the cgroup's memory.max");
  system.dir.write("cgroup/box/job/memory.max", std::to_string(100000 * kKiB) + "\n");
  system.dir.write("cgroup/box/job/memory.current", std::to_string(40000 * kKiB) + "\n");
  CHECK(memory_limit(system.sources).bytes == 60000 * kKiB);
}

TEST_CASE("memory: nothing readable means no limit", "[scene][memory]") {
  MemorySources nowhere;
  nowhere.proc = "/nonexistent/proc";
  nowhere.cgroup_root = "/nonexistent/cgroup";
  CHECK(memory_limit(nowhere).bytes == UINT64_MAX);
}

TEST_CASE("memory: a mesh stops loading where its tables pass the memory left, with the figures",
          "[scene][memory][obj][errors]") {
  // 200k vertices and 200k triangles: about 10 MiB of tables from 7 MB of text.
  std::string text;
  for (int i = 0; i < 200000; ++i) text += "v " + std::to_string(i) + " 0 1\n";
  for (int i = 1; i + 2 <= 200000; ++i)
    text += "f " + std::to_string(i) + " " + std::to_string(i + 1) + " " + std::to_string(i + 2) + "\n";
  test::ScratchDir dir;
  const std::string path = dir.write("big.obj", text);
  const MemoryLimit eight{8 << 20, "a test's limit"};
  try {
    load_obj_mesh(path, disk_files(), eight);
    FAIL("the mesh loaded within 8 MiB");
  } catch (const MeshError& e) {
    const std::string what = e.what();
    CHECK_THAT(what, Catch::StartsWith(path + ":"));
    CHECK_THAT(what, Catch::Contains(": loading stopped here: the mesh needs more than ") &&
                         Catch::EndsWith(" MiB, 8.0 MiB available (a test's limit)"));
  }
  CHECK(load_obj_mesh(path, disk_files(), {64 << 20, "a test's limit"}).corners.size() == 3 * 199998);
}

// clrt's program cache seen from the command line: a first run stores the compiled program (on
// PoCL, without CLRT_CACHE_DIR, a process of its own does after the image), later runs take it
// and render the same bytes; a damaged entry or a cache folder that cannot be made costs only the
// time of a build from source.
#include <catch2/catch.hpp>

#include <chrono>
#include <filesystem>
#include <string>
#include <thread>
#include <vector>

#include "render_support.hpp"
#include "scratch_dir.hpp"

using namespace clrt;
using namespace clrt::test;

namespace {

std::string render(const ScratchDir& dir, const std::string& cache, const std::string& out) {
  const CommandResult r = run_clrt(quoted(test_scene("area.ray")) +
                                       " -q --resolution 32x24 --spp 2 -o " + quoted(dir.file(out)),
                                   "CLRT_CACHE_DIR=" + quoted(cache));
  INFO(r.output);
  REQUIRE(r.exit_code == 0);
  CHECK(r.output.empty());
  return file_bytes(dir.file(out));
}

std::vector<std::filesystem::path> entries(const std::string& folder) {
  std::vector<std::filesystem::path> found;
  for (const auto& e : std::filesystem::directory_iterator(folder)) found.push_back(e.path());
  return found;
}

}  // namespace

TEST_CASE("the program is cached once and the cached one renders the same bytes",
          "[program-cache]") {
  ScratchDir dir;
  const std::string cache = dir.file("cache");
  const std::string first = render(dir, cache, "first.pfm");
  const auto stored = entries(cache);
  REQUIRE(stored.size() == 1);
  const std::string entry = file_bytes(stored[0].string());
  CHECK(render(dir, cache, "second.pfm") == first);
  CHECK(entries(cache) == stored);
  CHECK(file_bytes(stored[0].string()) == entry);
}

TEST_CASE("a damaged cache entry is rebuilt from source, with the same bytes", "[program-cache]") {
  ScratchDir dir;
  const std::string cache = dir.file("cache");
  const std::string first = render(dir, cache, "first.pfm");
  const std::filesystem::path entry = entries(cache).at(0);
  // The entry's own header, so the cache takes it, followed by bytes no driver accepts.
  const std::string stored = file_bytes(entry.string());
  const std::string header = stored.substr(0, stored.find('\n', stored.find('\n') + 1) + 1);
  dir.write("cache/" + entry.filename().string(), header + "not a program binary");
  CHECK(render(dir, cache, "again.pfm") == first);
  CHECK(file_bytes(entry.string()).size() > header.size() + 100);
}

TEST_CASE("a cache folder that cannot be made is no error", "[program-cache]") {
  ScratchDir dir;
  const std::string reference = render(dir, dir.file("cache"), "reference.pfm");
  const std::string blocker = dir.write("blocker", "a file where the cache's parent would be");
  CHECK(render(dir, blocker + "/cache", "uncached.pfm") == reference);
}

namespace background_store_test {

// The files of `folder` whose names end in `suffix`.
std::vector<std::filesystem::path> named(const std::string& folder, const std::string& suffix) {
  std::vector<std::filesystem::path> found;
  if (!std::filesystem::is_directory(folder)) return found;
  for (const auto& e : std::filesystem::directory_iterator(folder)) {
    const std::string name = e.path().filename().string();
    if (name.size() >= suffix.size() && name.compare(name.size() - suffix.size(), suffix.size(), suffix) == 0)
      found.push_back(e.path());
  }
  return found;
}

}  // namespace background_store_test

TEST_CASE("without CLRT_CACHE_DIR the program is cached in XDG_CACHE_HOME, on PoCL by a process of its own after the image",
          "[program-cache]") {
  using background_store_test::named;
  ScratchDir dir;
  const std::string xdg = dir.file("xdg"), folder = xdg + "/clrt";
  const std::string environment = "-u CLRT_CACHE_DIR XDG_CACHE_HOME=" + quoted(xdg);
  const auto render_here = [&](const std::string& out) {
    const CommandResult r = run_clrt(quoted(test_scene("area.ray")) + " -q --resolution 32x24 --spp 2 -o " +
                                         quoted(dir.file(out)), environment);
    INFO(r.output);
    REQUIRE(r.exit_code == 0);
    CHECK(r.output.empty());
    return file_bytes(dir.file(out));
  };
  const std::string first = render_here("first.pfm");
  // On PoCL the entry comes from the background process, whose request is gone once it is done;
  // on other drivers from the render itself.
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::minutes(5);
  while ((named(folder, ".bin").empty() || !named(folder, ".request").empty()) &&
         std::chrono::steady_clock::now() < deadline)
    std::this_thread::sleep_for(std::chrono::milliseconds(200));
  const auto stored = named(folder, ".bin");
  REQUIRE(stored.size() == 1);
  CHECK(named(folder, ".request").empty());
  const std::string entry = file_bytes(stored[0].string());
  CHECK(render_here("second.pfm") == first);
  CHECK(named(folder, ".request").empty());
  CHECK(file_bytes(stored[0].string()) == entry);
  CHECK(first == render(dir, dir.file("cache"), "named.pfm"));
}

TEST_CASE("the background store takes only a whole request for a device present, and removes it",
          "[program-cache]") {
  ScratchDir dir;
  const auto store = [&](const std::string& request) {
    return run_clrt("--internal-store-program " + quoted(request));
  };
  CHECK(store(dir.file("missing.request")).exit_code == 1);
  const std::string garbage = dir.write("cache/garbage.request", "not a request\n");
  CHECK(store(garbage).exit_code == 1);
  CHECK_FALSE(std::filesystem::exists(garbage));
  const std::string elsewhere = dir.write("cache/elsewhere.request",
                                          "clrt program store request 1\nNo Such Platform\nNo Such Device\n"
                                          "1.0\n0\n__kernel void k(__global int* a) { a[0] = 1; }\n");
  CHECK(store(elsewhere).exit_code == 1);
  CHECK_FALSE(std::filesystem::exists(elsewhere));
  CHECK(background_store_test::named(dir.file("cache"), ".bin").empty());
}

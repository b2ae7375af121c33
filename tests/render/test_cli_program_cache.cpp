// clrt's program cache seen from the command line: a first run stores the compiled program, later
// runs take it and render the same bytes; a damaged entry or a cache folder that cannot be made
// costs only the time of a build from source.
#include <catch2/catch.hpp>

#include <filesystem>
#include <string>

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

TEST_CASE("PoCL, which keeps its compiled kernels itself, gets clrt's cache only where CLRT_CACHE_DIR names it",
          "[program-cache]") {
  ScratchDir dir;
  const std::string home = dir.file("home"), xdg = dir.file("xdg");
  const CommandResult r = run_clrt(quoted(test_scene("area.ray")) + " -q --resolution 32x24 --spp 2 -o " +
                                       quoted(dir.file("uncached.pfm")),
                                   "-u CLRT_CACHE_DIR HOME=" + quoted(home) + " XDG_CACHE_HOME=" + quoted(xdg));
  INFO(r.output);
  REQUIRE(r.exit_code == 0);
  CHECK_FALSE(std::filesystem::exists(xdg));
  CHECK_FALSE(std::filesystem::exists(home));
  CHECK(file_bytes(dir.file("uncached.pfm")) == render(dir, dir.file("cache"), "cached.pfm"));
}

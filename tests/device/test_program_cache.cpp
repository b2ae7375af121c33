// The on-disk program cache: where it lives, what a hit needs, and that a damaged or foreign file
// is a miss, never an error. (clrt falling back to source on a binary the driver refuses is
// tested end to end in tests/render/test_cli_program_cache.cpp.)
#include <catch2/catch.hpp>

#include <sys/stat.h>

#include <cstdlib>
#include <fstream>
#include <iterator>
#include <optional>

#include "device/program_cache.hpp"
#include "scratch_dir.hpp"

using clrt::ProgramCache;

namespace {

std::string contents(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
}

// Sets an environment variable (or unsets it, for nullptr) for one scope.
class ScopedEnv {
 public:
  ScopedEnv(const char* name, const char* value) : name_(name) {
    if (const char* old = std::getenv(name)) old_ = old;
    set(value);
  }
  ~ScopedEnv() { set(old_ ? old_->c_str() : nullptr); }

 private:
  void set(const char* value) {
    if (value)
      ::setenv(name_, value, 1);
    else
      ::unsetenv(name_);
  }
  const char* name_;
  std::optional<std::string> old_;
};

}  // namespace

TEST_CASE("a stored binary comes back for the same identity only", "[program-cache]") {
  clrt::test::ScratchDir dir;
  const ProgramCache cache(dir.path() / "made-on-store", "source A\noptions");
  CHECK_FALSE(cache.load());
  const std::string binary("\x7f" "ELF\0binary bytes\n", 18);
  cache.store(binary);
  REQUIRE(cache.load() == binary);
  CHECK(ProgramCache(dir.path() / "made-on-store", "source A\noptions").load() == binary);
  CHECK_FALSE(ProgramCache(dir.path() / "made-on-store", "source B\noptions").load());
  // Nothing but the entry is left: the temporary was renamed into place.
  CHECK(std::distance(std::filesystem::directory_iterator(dir.path() / "made-on-store"),
                      std::filesystem::directory_iterator()) == 1);
  cache.forget();
  CHECK_FALSE(cache.load());
}

TEST_CASE("a file under the entry's name with another header is a miss", "[program-cache]") {
  clrt::test::ScratchDir dir;
  const ProgramCache cache(dir.path(), "identity");
  cache.store("binary");
  const std::string stored = contents(cache.file());
  for (const std::string& damaged :
       {std::string(), std::string("binary"), stored.substr(0, stored.size() - 6),
        std::string("clrt program binary 1\n0000000000000000\nbinary")}) {
    INFO(damaged);
    dir.write(cache.file().filename().string(), damaged);
    CHECK_FALSE(cache.load());
  }
}

TEST_CASE("an entry cut short, or with any byte changed, is a miss", "[program-cache]") {
  clrt::test::ScratchDir dir;
  const ProgramCache cache(dir.path(), "identity");
  const std::string payload = "a payload of some length\n\x01\x02 with binary bytes";
  cache.store(payload);
  const std::string stored = contents(cache.file());
  REQUIRE(cache.load() == payload);
  for (std::size_t cut = 0; cut < stored.size(); cut += 3) {
    INFO("cut to " << cut << " bytes");
    dir.write(cache.file().filename().string(), stored.substr(0, cut));
    CHECK_FALSE(cache.load());
  }
  for (std::size_t at = 0; at < stored.size(); ++at) {
    std::string flipped = stored;
    flipped[at] = static_cast<char>(flipped[at] ^ 0x10);
    INFO("bit 4 of byte " << at << " flipped");
    dir.write(cache.file().filename().string(), flipped);
    CHECK_FALSE(cache.load());
  }
}

TEST_CASE("a FIFO or a folder under the entry's name is a miss, without blocking", "[program-cache]") {
  clrt::test::ScratchDir dir;
  const ProgramCache cache(dir.path(), "identity");
  REQUIRE(::mkfifo(cache.file().c_str(), 0600) == 0);
  CHECK_FALSE(cache.load());  // a blocking open would wait here for a writer forever
  std::filesystem::remove(cache.file());
  std::filesystem::create_directory(cache.file());
  CHECK_FALSE(cache.load());
}

TEST_CASE("a folder that cannot be made leaves the cache empty, quietly", "[program-cache]") {
  clrt::test::ScratchDir dir;
  const std::string file = dir.write("not-a-folder", "x");
  const ProgramCache cache(std::filesystem::path(file) / "cache", "identity");
  cache.store("binary");
  CHECK_FALSE(cache.load());
}

TEST_CASE("the folder comes from CLRT_CACHE_DIR, XDG_CACHE_HOME or HOME", "[program-cache]") {
  {
    ScopedEnv own("CLRT_CACHE_DIR", "/somewhere/clrt");
    CHECK(ProgramCache::folder_from_environment() == std::filesystem::path("/somewhere/clrt"));
    CHECK(ProgramCache::named_by_environment());
    ScopedEnv off("CLRT_CACHE_DIR", "");
    CHECK_FALSE(ProgramCache::folder_from_environment());
    CHECK_FALSE(ProgramCache::named_by_environment());
  }
  ScopedEnv own("CLRT_CACHE_DIR", nullptr);
  CHECK_FALSE(ProgramCache::named_by_environment());
  {
    ScopedEnv xdg("XDG_CACHE_HOME", "/xdg");
    CHECK(ProgramCache::folder_from_environment() == std::filesystem::path("/xdg/clrt"));
  }
  ScopedEnv xdg("XDG_CACHE_HOME", nullptr);
  {
    ScopedEnv home("HOME", "/home/user");
    CHECK(ProgramCache::folder_from_environment() == std::filesystem::path("/home/user/.cache/clrt"));
    // A relative XDG_CACHE_HOME is invalid by the XDG specification: HOME's cache is used.
    ScopedEnv relative("XDG_CACHE_HOME", "relative/cache");
    CHECK(ProgramCache::folder_from_environment() == std::filesystem::path("/home/user/.cache/clrt"));
  }
  ScopedEnv home("HOME", nullptr);
  CHECK_FALSE(ProgramCache::folder_from_environment());
}

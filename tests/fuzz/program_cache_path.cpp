#include <filesystem>
#include <fstream>
#include <iterator>

#include "device/program_cache.hpp"
#include "fuzz_input_file.hpp"
#include "fuzz_paths.hpp"
#include "fuzz_require.hpp"

namespace fs = std::filesystem;

namespace clrt::fuzz {

Outcome program_cache_entry(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  const std::string bytes{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
  const ProgramCache cache(fs::path(input_dir()) / "program-cache", "a fuzzed identity");
  fs::create_directories(cache.file().parent_path());
  fs::copy_file(path, cache.file(), fs::copy_options::overwrite_existing);
  const std::optional<std::string> loaded = cache.load();
  if (loaded)
    require(bytes.size() > loaded->size() &&
                bytes.compare(bytes.size() - loaded->size(), loaded->size(), *loaded) == 0,
            "a loaded payload is not the end of its entry");
  // No program is empty, and load() refuses an empty payload.
  if (!bytes.empty()) {
    cache.store(bytes);
    require(cache.load() == bytes, "a stored payload did not load back whole");
    fs::resize_file(cache.file(), fs::file_size(cache.file()) - 1);
    require(!cache.load(), "an entry cut short by a byte was loaded");
  }
  cache.forget();
  return loaded ? Outcome::Accepted : Outcome::Rejected;
}

}  // namespace clrt::fuzz

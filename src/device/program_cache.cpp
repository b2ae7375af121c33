#include "device/program_cache.hpp"

#include <cstdint>
#include <cstdlib>
#include <system_error>

#include "device/cache_file.hpp"
#include "math/fnv1a.hpp"

namespace clrt {
namespace {

constexpr const char* kMagic = "clrt program binary 2\n";
constexpr std::uint64_t kPayloadBasis = 0x9e3779b97f4a7c15ull;
// The most an entry may hold: programs of clrt are a few MB; anything larger is not ours.
constexpr std::uintmax_t kLargestEntry = std::uintmax_t{256} << 20;

std::optional<std::filesystem::path> environment_path(const char* name) {
  const char* value = std::getenv(name);
  if (value == nullptr || *value == '\0') return std::nullopt;
  return std::filesystem::path(value);
}

}  // namespace

std::optional<std::filesystem::path> ProgramCache::folder_from_environment() {
  if (const char* own = std::getenv("CLRT_CACHE_DIR"))
    return *own == '\0' ? std::nullopt : std::optional<std::filesystem::path>(own);
  // The XDG base directory specification: a relative path there is invalid and is ignored.
  if (auto xdg = environment_path("XDG_CACHE_HOME"); xdg && xdg->is_absolute()) return *xdg / "clrt";
  if (auto home = environment_path("HOME")) return *home / ".cache" / "clrt";
  return std::nullopt;
}

bool ProgramCache::named_by_environment() {
  const char* own = std::getenv("CLRT_CACHE_DIR");
  return own != nullptr && *own != '\0';
}

ProgramCache::ProgramCache(std::filesystem::path folder, const std::string& identity)
    : folder_(std::move(folder)),
      file_(folder_ / (hex(fnv1a(identity)) + ".bin")),
      check_(std::string(kMagic) + hex(fnv1a(identity, 0x84222325cbf29ce4ull)) + "\n") {}

std::optional<std::string> ProgramCache::load() const {
  const std::optional<std::string> entry = read_cache_file(file_, kLargestEntry);
  if (!entry) return std::nullopt;
  // check_, then the payload's own checksum on a line, then the payload.
  const std::size_t sum_end = check_.size() + 17;
  if (entry->size() <= sum_end || entry->compare(0, check_.size(), check_) != 0 ||
      (*entry)[sum_end - 1] != '\n')
    return std::nullopt;
  std::string payload = entry->substr(sum_end);
  if (entry->compare(check_.size(), 16, hex(fnv1a(payload, kPayloadBasis))) != 0) return std::nullopt;
  return payload;
}

void ProgramCache::store(const std::string& payload) const {
  write_cache_file(file_, check_ + hex(fnv1a(payload, kPayloadBasis)) + "\n" + payload);
}

void ProgramCache::forget() const {
  std::error_code error;
  std::filesystem::remove(file_, error);
}

}  // namespace clrt

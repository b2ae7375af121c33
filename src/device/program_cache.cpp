#include "device/program_cache.hpp"

#include <unistd.h>

#include <cstdint>
#include <cstdlib>
#include <fstream>
#include <system_error>

namespace clrt {
namespace {

constexpr const char* kMagic = "clrt program binary 1\n";

// FNV-1a, 64 bits, from a chosen basis: two bases give two independent hashes of one text.
std::uint64_t fnv1a(const std::string& text, std::uint64_t basis) {
  std::uint64_t h = basis;
  for (const unsigned char c : text) {
    h ^= c;
    h *= 0x100000001b3ull;
  }
  return h;
}

std::string hex(std::uint64_t value) {
  static const char* const digits = "0123456789abcdef";
  std::string out(16, '0');
  for (int i = 15; i >= 0; --i, value >>= 4) out[static_cast<std::size_t>(i)] = digits[value & 15u];
  return out;
}

std::optional<std::filesystem::path> environment_path(const char* name) {
  const char* value = std::getenv(name);
  if (value == nullptr || *value == '\0') return std::nullopt;
  return std::filesystem::path(value);
}

}  // namespace

std::optional<std::filesystem::path> ProgramCache::folder_from_environment() {
  if (const char* own = std::getenv("CLRT_CACHE_DIR"))
    return *own == '\0' ? std::nullopt : std::optional<std::filesystem::path>(own);
  if (auto xdg = environment_path("XDG_CACHE_HOME")) return *xdg / "clrt";
  if (auto home = environment_path("HOME")) return *home / ".cache" / "clrt";
  return std::nullopt;
}

ProgramCache::ProgramCache(std::filesystem::path folder, const std::string& identity)
    : folder_(std::move(folder)),
      file_(folder_ / (hex(fnv1a(identity, 0xcbf29ce484222325ull)) + ".bin")),
      check_(std::string(kMagic) + hex(fnv1a(identity, 0x84222325cbf29ce4ull)) + "\n") {}

std::optional<std::string> ProgramCache::load() const {
  std::ifstream in(file_, std::ios::binary | std::ios::ate);
  if (!in) return std::nullopt;
  const std::streamoff size = in.tellg();
  if (size <= static_cast<std::streamoff>(check_.size())) return std::nullopt;
  std::string header(check_.size(), '\0');
  in.seekg(0);
  if (!in.read(header.data(), static_cast<std::streamsize>(header.size())) || header != check_)
    return std::nullopt;
  std::string binary(static_cast<std::size_t>(size) - check_.size(), '\0');
  if (!in.read(binary.data(), static_cast<std::streamsize>(binary.size()))) return std::nullopt;
  return binary;
}

void ProgramCache::store(const std::string& binary) const {
  std::error_code error;
  std::filesystem::create_directories(folder_, error);
  if (error) return;
  std::filesystem::path temporary = file_;
  temporary += "." + std::to_string(::getpid()) + ".tmp";
  {
    std::ofstream out(temporary, std::ios::binary | std::ios::trunc);
    out << check_ << binary;
    out.close();
    if (!out) {
      std::filesystem::remove(temporary, error);
      return;
    }
  }
  std::filesystem::rename(temporary, file_, error);
  if (error) std::filesystem::remove(temporary, error);
}

void ProgramCache::forget() const {
  std::error_code error;
  std::filesystem::remove(file_, error);
}

}  // namespace clrt

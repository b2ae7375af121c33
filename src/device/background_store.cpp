#include "device/background_store.hpp"

#include <fcntl.h>
#include <spawn.h>
#include <sys/resource.h>
#include <unistd.h>

#include <chrono>
#include <cstdlib>
#include <mutex>
#include <sstream>
#include <system_error>
#include <vector>

#include "device/cache_file.hpp"
#include "device/device_context.hpp"

extern char** environ;

namespace clrt {
namespace {

constexpr const char* kRequestMagic = "clrt program store request 1";
// A request this young means a store of the same program is under way; an older one is left
// from a process that died.
constexpr auto kRequestLifetime = std::chrono::minutes(10);
// Programs of clrt are a few hundred KB of source: anything larger is no request of ours.
constexpr std::uintmax_t kLargestRequest = std::uintmax_t{16} << 20;

struct PendingStore {
  std::filesystem::path entry;
  std::string platform, device, driver, options, source;
};

std::mutex pending_mutex;
std::vector<PendingStore> pending;

std::filesystem::path request_of(const std::filesystem::path& entry) {
  std::filesystem::path request = entry;
  request.replace_extension(".request");
  return request;
}

// Platform, device and driver on a line each, the options' length and the options, the source.
std::string request_text(const PendingStore& store) {
  return std::string(kRequestMagic) + "\n" + store.platform + "\n" + store.device + "\n" +
         store.driver + "\n" + std::to_string(store.options.size()) + "\n" + store.options +
         store.source;
}

bool one_line(const std::string& text) { return text.find('\n') == std::string::npos; }

std::optional<PendingStore> parse_request(const std::string& text) {
  std::istringstream in(text);
  std::string magic, length;
  PendingStore store;
  if (!std::getline(in, magic) || magic != kRequestMagic || !std::getline(in, store.platform) ||
      !std::getline(in, store.device) || !std::getline(in, store.driver) || !std::getline(in, length) ||
      length.empty() || length.size() > 6 || length.find_first_not_of("0123456789") != std::string::npos)
    return std::nullopt;
  const std::size_t options_at = static_cast<std::size_t>(in.tellg());
  const std::size_t options_size = std::stoul(length);
  if (options_at + options_size > text.size()) return std::nullopt;
  store.options = text.substr(options_at, options_size);
  store.source = text.substr(options_at + options_size);
  return store;
}

bool request_under_way(const std::filesystem::path& request) {
  std::error_code error;
  const auto written = std::filesystem::last_write_time(request, error);
  return !error && std::filesystem::file_time_type::clock::now() - written < kRequestLifetime;
}

bool spawn_store(const std::filesystem::path& request) {
  posix_spawn_file_actions_t actions;
  posix_spawnattr_t attributes;
  if (posix_spawn_file_actions_init(&actions) != 0) return false;
  if (posix_spawnattr_init(&attributes) != 0) {
    posix_spawn_file_actions_destroy(&actions);
    return false;
  }
  for (int fd = 0; fd <= 2; ++fd)
    posix_spawn_file_actions_addopen(&actions, fd, "/dev/null", fd == 0 ? O_RDONLY : O_WRONLY, 0);
  // Its own session: a terminal's hang-up or Ctrl-C after clrt has returned is not for it.
  posix_spawnattr_setflags(&attributes, POSIX_SPAWN_SETSID);
  // Named as it was started, so that `ps` shows which program this is.
  std::error_code error;
  std::string self = std::filesystem::read_symlink("/proc/self/exe", error).string();
  if (error) return false;
  std::string argument = kStoreProgramArgument, path = request.string();
  char* argv[] = {self.data(), argument.data(), path.data(), nullptr};
  pid_t pid = 0;
  const bool started = posix_spawn(&pid, self.c_str(), &actions, &attributes, argv, environ) == 0;
  posix_spawn_file_actions_destroy(&actions);
  posix_spawnattr_destroy(&attributes);
  return started;
}

}  // namespace

void defer_program_store(const std::filesystem::path& entry, const compute::device& device,
                         const std::string& options, const std::string& source) {
  PendingStore store{entry, device.platform().name(), device.name(), device.driver_version(), options, source};
  if (!one_line(store.platform) || !one_line(store.device) || !one_line(store.driver)) return;
  const std::lock_guard<std::mutex> lock(pending_mutex);
  for (const PendingStore& p : pending)
    if (p.entry == entry) return;
  pending.push_back(std::move(store));
}

void start_background_stores() {
  std::vector<PendingStore> stores;
  {
    const std::lock_guard<std::mutex> lock(pending_mutex);
    stores.swap(pending);
  }
  for (const PendingStore& store : stores) {
    const std::filesystem::path request = request_of(store.entry);
    if (request_under_way(request) || !write_cache_file(request, request_text(store))) continue;
    if (!spawn_store(request)) {
      std::error_code error;
      std::filesystem::remove(request, error);
    }
  }
}

int store_program_from_request(const std::filesystem::path& request) {
  // Behind whatever the user runs next.
  ::setpriority(PRIO_PROCESS, 0, 19);
  const std::optional<std::string> text = read_cache_file(request, kLargestRequest);
  const std::optional<PendingStore> store = text ? parse_request(*text) : std::nullopt;
  int status = 1;
  if (store) {
    try {
      for (const DeviceEntry& entry : enumerate_devices()) {
        if (entry.device.platform().name() != store->platform || entry.device.name() != store->device ||
            entry.device.driver_version() != store->driver)
          continue;
        // Named by CLRT_CACHE_DIR, the request's folder is written in this process.
        setenv("CLRT_CACHE_DIR", request.parent_path().c_str(), 1);
        DeviceContext(entry).build(store->source, store->options);
        status = 0;
        break;
      }
    } catch (const std::exception&) {
      status = 1;
    }
  }
  std::error_code error;
  std::filesystem::remove(request, error);
  return status;
}

}  // namespace clrt

#include "image/interrupt_cleanup.hpp"

#include <fcntl.h>
#include <limits.h>
#include <unistd.h>

#include <array>
#include <atomic>
#include <csignal>
#include <cstdlib>
#include <cstring>

namespace clrt {
namespace {

enum SlotState : int { kFree, kFilling, kRegistered };

struct Slot {
  std::atomic<int> state{kFree};
  char path[PATH_MAX];
};

std::array<Slot, 64> slots;
static_assert(std::atomic<int>::is_always_lock_free, "the handlers read the slots");

extern "C" void on_termination_signal(int signal_number) {
  // Only async-signal-safe calls from here on.
  for (Slot& slot : slots)
    if (slot.state.load(std::memory_order_acquire) == kRegistered) ::unlink(slot.path);
  std::signal(signal_number, SIG_DFL);
  std::raise(signal_number);  // delivered when the handler returns: the default action ends us
}

}  // namespace

void remove_temporaries_on_signal() {
  static const bool installed = [] {
    struct sigaction action {};
    action.sa_handler = on_termination_signal;
    sigemptyset(&action.sa_mask);
    // Either signal arriving during the other's handler waits for it, then ends the process.
    sigaddset(&action.sa_mask, SIGINT);
    sigaddset(&action.sa_mask, SIGTERM);
    for (int signal_number : {SIGINT, SIGTERM}) ::sigaction(signal_number, &action, nullptr);
    return true;
  }();
  (void)installed;
}

namespace image_detail {

TemporaryRegistration::TemporaryRegistration(const std::string& path) {
  if (path.size() >= PATH_MAX) return;
  for (int i = 0; i < static_cast<int>(slots.size()); ++i) {
    int expected = kFree;
    if (!slots[i].state.compare_exchange_strong(expected, kFilling)) continue;
    std::memcpy(slots[i].path, path.c_str(), path.size() + 1);
    slots[i].state.store(kRegistered, std::memory_order_release);
    slot_ = i;
    return;
  }
}

TemporaryRegistration::~TemporaryRegistration() {
  if (slot_ >= 0) slots[static_cast<std::size_t>(slot_)].state.store(kFree, std::memory_order_release);
}

void hold_before_commit_for_tests(const std::string& temp_path) {
  const char* fifo = std::getenv("CLRT_TEST_HOLD_BEFORE_COMMIT");
  if (!fifo || !*fifo) return;
  const int fd = ::open(fifo, O_WRONLY | O_CLOEXEC);
  if (fd < 0) return;
  const std::string line = temp_path + "\n";
  const ssize_t written = ::write(fd, line.data(), line.size());
  ::close(fd);
  if (written == static_cast<ssize_t>(line.size()))
    for (;;) ::pause();
}

}  // namespace image_detail
}  // namespace clrt

#include "image/interrupt_cleanup.hpp"

#include <fcntl.h>
#include <pthread.h>
#include <unistd.h>

#include <atomic>
#include <chrono>
#include <csignal>
#include <cstdlib>
#include <mutex>
#include <set>
#include <string>
#include <thread>

namespace clrt {
namespace {

constexpr int kEndingSignals[] = {SIGINT,  SIGTERM, SIGHUP,  SIGQUIT, SIGALRM,
                                  SIGPIPE, SIGUSR1, SIGUSR2, SIGXFSZ};

struct Temporaries {
  std::mutex mutex;
  std::set<std::string> paths;
};

std::atomic<bool> accepting_stop_requests{false};
std::atomic<int> requested_stop{0};

// Takes the first SIGINT or SIGTERM as a request to stop while requests are accepted.
bool taken_as_stop_request(int signal_number) {
  if ((signal_number != SIGINT && signal_number != SIGTERM) || !accepting_stop_requests.load())
    return false;
  int none = 0;
  return requested_stop.compare_exchange_strong(none, signal_number);
}

// Writes `line` to the FIFO `fifo`; whether it was all written.
bool tell_fifo(const std::string& fifo, const std::string& line) {
  const int fd = ::open(fifo.c_str(), O_WRONLY | O_CLOEXEC);
  if (fd < 0) return false;
  const ssize_t written = ::write(fd, line.data(), line.size());
  ::close(fd);
  return written == static_cast<ssize_t>(line.size());
}

// Never destroyed: a signal may come while static objects are destroyed at exit.
Temporaries& temporaries() {
  static Temporaries* const all = new Temporaries;
  return *all;
}

sigset_t ending_signals() {
  sigset_t set;
  sigemptyset(&set);
  for (int signal_number : kEndingSignals) sigaddset(&set, signal_number);
  return set;
}

// Those ignored from the start (nohup ignores SIGHUP) stay ignored. They are blocked all the
// same and dropped when taken: left unblocked, a handler LLVM installs over SIG_IGN would run,
// and LLVM's handler unblocks every signal in its thread, which would then die by the next one
// without removing the temporaries.
sigset_t ignored_from_start() {
  sigset_t set;
  sigemptyset(&set);
  for (int signal_number : kEndingSignals) {
    struct sigaction current {};
    if (::sigaction(signal_number, nullptr, &current) == 0 && current.sa_handler == SIG_IGN)
      sigaddset(&set, signal_number);
  }
  return set;
}

[[noreturn]] void end_by(int signal_number) {
  Temporaries& all = temporaries();
  // Never unlocked: no temporary is created or put in place from here on.
  all.mutex.lock();
  for (const std::string& path : all.paths) ::unlink(path.c_str());
  std::signal(signal_number, SIG_DFL);
  sigset_t just_this;
  sigemptyset(&just_this);
  sigaddset(&just_this, signal_number);
  ::pthread_sigmask(SIG_UNBLOCK, &just_this, nullptr);
  std::raise(signal_number);
  std::_Exit(128 + signal_number);  // only if the default action did not end the process
}

}  // namespace

void remove_temporaries_on_signal() {
  static const bool started = [] {
    const sigset_t set = ending_signals(), ignored = ignored_from_start();
    ::pthread_sigmask(SIG_BLOCK, &set, nullptr);
    std::thread([set, ignored] {
      int signal_number = 0;
      for (;;) {
        while (::sigwait(&set, &signal_number) != 0 || sigismember(&ignored, signal_number) == 1) {
        }
        if (!taken_as_stop_request(signal_number)) end_by(signal_number);
      }
    }).detach();
    return true;
  }();
  (void)started;
}

void end_by_pending_signal() {
  sigset_t pending;
  if (::sigpending(&pending) != 0) return;
  for (int signal_number : {SIGPIPE, SIGXFSZ})
    if (sigismember(&pending, signal_number) == 1) end_by(signal_number);
}

void accept_stop_requests(bool accept) { accepting_stop_requests.store(accept); }

int stop_request() { return requested_stop.load(); }

void end_by_stop_request() {
  if (const int signal_number = requested_stop.load()) end_by(signal_number);
}

void hold_after_round_for_tests(unsigned rounds_done) {
  const char* hold = std::getenv("CLRT_TEST_HOLD_AFTER_ROUND");
  if (!hold || !*hold) return;
  const std::string text(hold);
  const std::size_t colon = text.find(':');
  if (colon == std::string::npos || text.substr(0, colon) != std::to_string(rounds_done)) return;
  if (!tell_fifo(text.substr(colon + 1), "round " + std::to_string(rounds_done) + "\n")) return;
  while (stop_request() == 0) std::this_thread::sleep_for(std::chrono::milliseconds(5));
}

namespace image_detail {

void change_temporary(const std::string& path, const std::function<bool()>& step) {
  Temporaries& all = temporaries();
  const std::lock_guard<std::mutex> lock(all.mutex);
  if (step())
    all.paths.insert(path);
  else
    all.paths.erase(path);
}

void hold_before_commit_for_tests(const std::string& temp_path) {
  const char* fifo = std::getenv("CLRT_TEST_HOLD_BEFORE_COMMIT");
  if (!fifo || !*fifo) return;
  if (tell_fifo(fifo, temp_path + "\n"))
    for (;;) ::pause();
}

}  // namespace image_detail
}  // namespace clrt

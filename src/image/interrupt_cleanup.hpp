// SIGINT and SIGTERM must not leave an AtomicFile's temporary behind: the handlers remove every
// temporary that exists at that moment, then end the process by the same signal, so a shell
// still sees an interrupted program ($? is 130 or 143) and stops a loop running it.
#pragma once

#include <string>

namespace clrt {

// Installs the handlers (once per process; later calls do nothing).
void remove_temporaries_on_signal();

namespace image_detail {

// The temporaries the handlers remove: AtomicFile registers its path before creating the file
// and releases the entry once the file is renamed or removed. Safe from any thread and from
// the handlers. A path that finds no free entry (more than 64 writes at once) or is longer than
// PATH_MAX is not registered: its temporary would survive a signal.
class TemporaryRegistration {
 public:
  explicit TemporaryRegistration(const std::string& path);
  ~TemporaryRegistration();
  TemporaryRegistration(const TemporaryRegistration&) = delete;
  TemporaryRegistration& operator=(const TemporaryRegistration&) = delete;

 private:
  int slot_ = -1;
};

// For the test that signals clrt in the middle of a write: when CLRT_TEST_HOLD_BEFORE_COMMIT
// names a FIFO, writes `temp_path` and a newline to it, then waits for a signal forever.
// Without the variable it does nothing.
void hold_before_commit_for_tests(const std::string& temp_path);

}  // namespace image_detail
}  // namespace clrt

// Runs the clrt executable as a child process the test controls: its own working directory,
// extra environment, and signals sent while it runs.
#pragma once

#include <sys/types.h>

#include <string>
#include <vector>

namespace clrt::test {

class ClrtProcess {
 public:
  // Starts clrt with `arguments` in `working_dir`, its environment being the test's plus
  // `extra_environment` ("NAME=value" each); the signals that end clrt start with their default
  // action even if the test inherited them ignored, but for `inherited` (which it gets as the
  // test has them, e.g. ignored as nohup does). Output goes to `output_file`.
  ClrtProcess(const std::vector<std::string>& arguments, const std::string& working_dir,
              const std::vector<std::string>& extra_environment, const std::string& output_file,
              const std::vector<int>& inherited = {});
  ~ClrtProcess();  // kills the child if it is still running
  ClrtProcess(const ClrtProcess&) = delete;
  ClrtProcess& operator=(const ClrtProcess&) = delete;

  pid_t pid() const { return pid_; }
  // Blocks until the child ends; returns its wait status (see <sys/wait.h>).
  int wait();
  // True (and the status set) if the child has ended, without blocking.
  bool ended(int& status);

 private:
  pid_t pid_ = -1;
  bool reaped_ = false;
};

// Reads the line clrt writes to `fifo` when a test hook holds it (CLRT_TEST_HOLD_BEFORE_COMMIT,
// CLRT_TEST_HOLD_AFTER_ROUND), without its newline; fails the test if clrt ends first.
std::string read_fifo_line(const std::string& fifo, ClrtProcess& clrt);

}  // namespace clrt::test

// Running one process and measuring it from the outside: wall time, exit code, peak memory.
#pragma once

#include <string>
#include <vector>

namespace clrt::experiment {

struct ProcessResult {
  int exit_code = -1;        // 128 + signal when killed; -1 when it could not start
  double wall_seconds = 0;
  double peak_rss_bytes = 0;  // the child's maximum resident set (wait4's rusage)
  std::string out, err;       // its standard output and standard error
};

// Runs args[0] (a path) with `args`, `environment` ("NAME=value" entries) added to ours.
ProcessResult run_process(const std::vector<std::string>& args,
                          const std::vector<std::string>& environment = {});

}  // namespace clrt::experiment

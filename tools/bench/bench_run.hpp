// Running one clrt process and measuring it from the outside.
#pragma once

#include <string>
#include <vector>

namespace clrt::bench {

struct RunResult {
  int exit_code = -1;
  double wall_seconds = 0;
  double peak_rss_bytes = 0;  // the child's maximum resident set (wait4's rusage)
  std::string output;         // its standard output
};

RunResult run_process(const std::vector<std::string>& args);

// Files named, and the .ray files (sorted) of folders named.
std::vector<std::string> expand_scenes(const std::vector<std::string>& paths);

}  // namespace clrt::bench

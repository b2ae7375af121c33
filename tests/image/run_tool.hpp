// Runs the built executables through the shell, for their end-to-end tests.
#pragma once

#include <sys/wait.h>

#include <catch2/catch.hpp>
#include <cstdlib>
#include <string>

#include "test_files.hpp"

namespace clrt::test {

struct ToolResult {
  int status = -1;
  Bytes out;  // standard output as bytes: it may hold an image
  std::string err;
  std::string out_text() const { return {out.begin(), out.end()}; }
};

inline std::string quoted(const std::string& path) { return "'" + path + "'"; }

// `executable` with `args` (already shell-quoted where needed); both streams go to files in
// `dir`.
inline ToolResult run_tool(const ScratchDir& dir, const std::string& executable,
                           const std::string& args) {
  const std::string out_path = dir.file("stdout.bin"), err_path = dir.file("stderr.txt");
  const std::string command =
      quoted(executable) + " " + args + " >" + quoted(out_path) + " 2>" + quoted(err_path);
  const int raw = std::system(command.c_str());
  REQUIRE(WIFEXITED(raw));
  const Bytes err = read_bytes(err_path);
  return {WEXITSTATUS(raw), read_bytes(out_path), std::string(err.begin(), err.end())};
}

#ifdef CLRT_IMG
inline ToolResult run_img(const ScratchDir& dir, const std::string& args) {
  return run_tool(dir, CLRT_IMG, args);
}
#endif

}  // namespace clrt::test

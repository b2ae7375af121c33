// libFuzzer hands its input as bytes; clrt's readers take paths. Each fuzz process writes every
// input to one file in a private directory, created on first use and removed at exit.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>

namespace clrt::fuzz {

// The directory (under $TMPDIR, else /tmp) that holds this process's input files.
const std::string& input_dir();

// Writes `size` bytes to input_dir()/name, replacing what was there, and returns its path.
// Aborts if the file cannot be written: a fuzz run that tests nothing must not look clean.
std::string write_input(const std::string& name, const std::uint8_t* data, std::size_t size);

}  // namespace clrt::fuzz

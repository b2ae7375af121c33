// The OpenCL C sources of kernels/, compiled into the binary, and their assembly into one
// program text with #include lines resolved and #line markers naming the real files.
#pragma once

#include <string>
#include <vector>

namespace clrt {

struct EmbeddedFile {
  const char* path;  // relative to kernels/, e.g. "shared/ray.h"
  const char* text;
};

// Every file of kernels/ (generated at build time by tools/cmake/EmbedKernels.cmake).
const std::vector<EmbeddedFile>& embedded_kernel_files();

// The text of kernels/`path`, or throws std::runtime_error when there is no such file.
const std::string& kernel_file(const std::string& path);

// Expands `#include "X"` lines (X relative to the including file, then to kernels/) from the
// embedded files, each file at most once, with `#line N "kernels/FILE"` markers so build logs
// name the real file and line. `name` labels `text` in those markers.
std::string assemble_kernel_source(const std::string& text, const std::string& name);

// The renderer's whole program: every kernels/*.cl stage file, assembled.
std::string renderer_program_source();

}  // namespace clrt

#include "text_file.hpp"

#include <cerrno>
#include <cstdarg>
#include <cstring>
#include <stdexcept>

namespace clrt::scenes {
namespace {

[[noreturn]] void fail(const std::string& path, const char* what) {
  throw std::runtime_error(path + ": " + what + ": " + std::strerror(errno));
}

}  // namespace

TextFile::TextFile(const std::string& path) : path_(path), file_(std::fopen(path.c_str(), "w")) {
  if (!file_) fail(path_, "cannot create");
}

TextFile::~TextFile() {
  if (file_) std::fclose(file_);
}

void TextFile::print(const char* format, ...) {
  va_list args;
  va_start(args, format);
  const int written = std::vfprintf(file_, format, args);
  va_end(args);
  if (written < 0) fail(path_, "cannot write");
}

void TextFile::close() {
  std::FILE* file = file_;
  file_ = nullptr;
  if (std::fclose(file) != 0) fail(path_, "cannot write");
}

}  // namespace clrt::scenes

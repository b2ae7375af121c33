// A text file written with printf-style formatting; every failure throws with the file's name.
#pragma once

#include <cstdio>
#include <string>

namespace clrt::scenes {

class TextFile {
 public:
  explicit TextFile(const std::string& path);
  ~TextFile();
  TextFile(const TextFile&) = delete;
  TextFile& operator=(const TextFile&) = delete;

  void print(const char* format, ...) __attribute__((format(printf, 2, 3)));
  // Flushes and closes; throws if anything was lost on the way to the disk.
  void close();

 private:
  std::string path_;
  std::FILE* file_;
};

}  // namespace clrt::scenes

// A file that appears at its path complete or not at all.
#pragma once

#include <cstddef>
#include <string>

#include "image/byte_sink.hpp"

namespace clrt::image_detail {

// Writes go to a temporary beside `path` (same folder, hence same file system, so the final
// rename is atomic), named .clrt-PID-N.tmp whatever the length of the file's own name. finish()
// flushes it to disk and renames it over `path`; any failure, destruction before finish(), or a
// signal once remove_temporaries_on_signal() is in place, removes the temporary and leaves
// `path` as it was. Errors are SinkError naming `name` (the path the user gave, which may be a
// link to `path`) and the system's reason.
class AtomicFile final : public ByteSink {
 public:
  AtomicFile(std::string path, std::string name);
  ~AtomicFile() override;

  void finish() override;

 protected:
  void write_through(const void* data, std::size_t size) override;

 private:
  // Reads errno, so call it straight after the failing system call.
  [[noreturn]] void fail(const std::string& step);
  void discard() noexcept;

  std::string path_, name_, temp_path_;
  int fd_ = -1;
  bool temp_exists_ = false;
};

// The folder `path` is in: "." for a bare name, "/" for one at the root.
std::string folder_of(const std::string& path);

}  // namespace clrt::image_detail

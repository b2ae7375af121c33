// A file that appears at its path complete or not at all.
#pragma once

#include <cstddef>
#include <optional>
#include <string>

#include "image/byte_sink.hpp"
#include "image/interrupt_cleanup.hpp"

namespace clrt::image_detail {

// Writes go to a temporary beside the target (same directory, hence same file system, so the
// final rename is atomic). finish() flushes it to disk and renames it over the target; any
// failure, or destruction before finish(), removes the temporary and leaves the target as it
// was, and so does SIGINT or SIGTERM once remove_temporaries_on_signal() has installed its
// handlers. Errors are ImageError naming the target path and the system's reason.
class AtomicFile final : public ByteSink {
 public:
  explicit AtomicFile(std::string path);
  ~AtomicFile() override;

  void finish() override;

 protected:
  void write_through(const void* data, std::size_t size) override;

 private:
  // Reads errno, so call it straight after the failing system call.
  [[noreturn]] void fail(const char* step);
  void discard() noexcept;

  std::string path_, temp_path_;
  int fd_ = -1;
  bool temp_exists_ = false;
  // Held from before the temporary is created until it is renamed or removed.
  std::optional<TemporaryRegistration> registration_;
};

}  // namespace clrt::image_detail

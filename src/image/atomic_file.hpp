// A file that appears at its path complete or not at all.
#pragma once

#include <sys/stat.h>

#include <cstddef>
#include <string>

#include "image/byte_sink.hpp"

namespace clrt::image_detail {

// Writes go to a temporary beside `path` (same folder, hence same file system, so the final
// rename is atomic), named .clrt-PID-N.tmp whatever the length of the file's own name. finish()
// flushes it to disk and renames it over `path`; any failure, destruction before finish(), or a
// signal once remove_temporaries_on_signal() is in place, removes the temporary and leaves
// `path` as it was. An existing `path` is replaced only as check_replaceable() allows, and the
// file that replaces it keeps its mode, and its owner and group where the system lets clrt set
// them (root: both; another user: the group, when the user is in it). Errors are SinkError
// naming `name` (the path the user gave, which may be a link to `path`) and the system's reason.
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

  // What the temporary takes on from the file it replaces, once created.
  void keep_metadata_of(const struct stat& replaced);

  std::string path_, name_, temp_path_;
  int fd_ = -1;
  bool temp_exists_ = false;
};

// Throws SinkError naming `name` when the existing regular file `path` may not be replaced:
// - one the user may not write, as access(W_OK) tells with the effective ids. So root may
//   replace a read-only file, as a shell's `>` lets it write one.
// - one with other hard links: a rename would part it from them, and they would keep the old
//   image while this name got the new one. Writing into it in place instead would lose the
//   all-or-nothing replacement that every other output has.
void check_replaceable(const std::string& path, const std::string& name);

// The folder `path` is in: "." for a bare name, "/" for one at the root.
std::string folder_of(const std::string& path);

}  // namespace clrt::image_detail

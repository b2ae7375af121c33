// Where the loaders get the files a scene names (the scene file, its OBJ meshes): from the disk,
// read whole and checked unchanged; or from memory, e.g. on an MPI rank that received rank 0's
// files, so that nodes need no shared file system. The disk source can also keep a copy of everything it
// served, which is what rank 0 sends.
#pragma once

#include <cstdint>
#include <map>
#include <memory>
#include <mutex>
#include <string>
#include <string_view>

namespace clrt {

// The bytes of one file, valid while this object lives.
class FileBytes {
 public:
  virtual ~FileBytes() = default;
  virtual std::string_view text() const = 0;
};

class FileSource {
 public:
  virtual ~FileSource() = default;
  // The file at `path` (as the loader resolved it). Throws InputFileError with the reason (no
  // path) for a file that cannot be read, is not a regular file (a folder, /dev/zero, a pipe)
  // or is larger than `max_bytes`; FileChangedError for one that changed while it was read.
  virtual std::unique_ptr<FileBytes> open(const std::string& path, std::uint64_t max_bytes) const = 0;
};

// The files on the disk.
const FileSource& disk_files();

// The disk, keeping a copy of each file it serves (once per path).
class RecordingFiles final : public FileSource {
 public:
  std::unique_ptr<FileBytes> open(const std::string& path, std::uint64_t max_bytes) const override;
  // Path -> bytes of everything served so far.
  const std::map<std::string, std::string>& files() const { return files_; }

 private:
  mutable std::mutex mutex_;
  mutable std::map<std::string, std::string> files_;
};

// Files held in memory, by path; any other path cannot be read.
class MemoryFiles final : public FileSource {
 public:
  explicit MemoryFiles(std::map<std::string, std::string> files) : files_(std::move(files)) {}
  std::unique_ptr<FileBytes> open(const std::string& path, std::uint64_t max_bytes) const override;

 private:
  std::map<std::string, std::string> files_;
};

}  // namespace clrt

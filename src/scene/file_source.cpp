#include "scene/file_source.hpp"

#include "image/input_file_checks.hpp"
#include "scene/file_in_memory.hpp"

namespace clrt {
namespace {

class DiskFiles final : public FileSource {
 public:
  std::unique_ptr<FileBytes> open(const std::string& path, std::uint64_t max_bytes) const override {
    return std::make_unique<FileInMemory>(path, max_bytes);
  }
};

// A view of bytes someone else keeps alive.
class BorrowedBytes final : public FileBytes {
 public:
  explicit BorrowedBytes(std::string_view text) : text_(text) {}
  std::string_view text() const override { return text_; }

 private:
  std::string_view text_;
};

}  // namespace

const FileSource& disk_files() {
  static const DiskFiles disk;
  return disk;
}

std::unique_ptr<FileBytes> RecordingFiles::open(const std::string& path,
                                                std::uint64_t max_bytes) const {
  std::unique_ptr<FileBytes> bytes = disk_files().open(path, max_bytes);
  std::lock_guard<std::mutex> lock(mutex_);
  files_.emplace(path, std::string(bytes->text()));
  return bytes;
}

std::unique_ptr<FileBytes> MemoryFiles::open(const std::string& path, std::uint64_t max_bytes) const {
  const auto it = files_.find(path);
  if (it == files_.end()) throw InputFileError("it is not among the scene's files");
  if (it->second.size() > max_bytes)
    throw InputFileError("it is larger than " + size_limit_text(max_bytes));
  return std::make_unique<BorrowedBytes>(it->second);
}

}  // namespace clrt

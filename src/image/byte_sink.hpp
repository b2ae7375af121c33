// Where encoders put their bytes: an atomic file or an open descriptor such as standard output.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace clrt::image_detail {

// Small writes are gathered into blocks, so encoders that emit many pieces (PNG chunk headers,
// rows) cost few system calls; large writes go straight through.
class ByteSink {
 public:
  virtual ~ByteSink() = default;
  void write(const void* data, std::size_t size);
  // After the last write: everything reaches the output, and a file is put in place.
  virtual void finish() { flush(); }

 protected:
  ByteSink() = default;
  ByteSink(const ByteSink&) = delete;
  ByteSink& operator=(const ByteSink&) = delete;
  void flush();
  virtual void write_through(const void* data, std::size_t size) = 0;

 private:
  std::vector<std::uint8_t> buffer_;
};

// A descriptor, written as it is: errors are ImageError naming `name`. The caller keeps it
// open, unless `owned`: then finish() closes it (a failed close fails the write) and so does
// destruction before finish().
class FdSink final : public ByteSink {
 public:
  FdSink(int fd, std::string name, bool owned = false)
      : fd_(fd), name_(std::move(name)), owned_(owned) {}
  ~FdSink() override;

  void finish() override;

 protected:
  void write_through(const void* data, std::size_t size) override;

 private:
  [[noreturn]] void fail(int error) const;

  int fd_;
  std::string name_;
  bool owned_;
};

// All `size` bytes to `fd`, retrying after signals and short writes: 0, or the errno of the
// failure.
int write_all(int fd, const void* data, std::size_t size);

}  // namespace clrt::image_detail

// OpenEXR streams over memory. OpenEXR seeks back to fill in its offset table, which a pipe
// cannot do, so a file is encoded into memory and then written to its sink; a file to read is
// loaded whole (through InputFile, for the same errors as every other format).
#pragma once

#include <OpenEXR/ImfIO.h>

#include <cstdint>
#include <vector>

#include "image/byte_span.hpp"

namespace clrt::image_detail {

class MemoryOStream final : public Imf::OStream {
 public:
  // `expected_bytes` is reserved up front: untouched capacity costs no memory, and the bytes
  // are never copied to a larger buffer as they grow.
  explicit MemoryOStream(std::size_t expected_bytes) : Imf::OStream("memory") {
    bytes_.reserve(expected_bytes);
  }
  void write(const char c[], int n) override;
  std::uint64_t tellp() override { return position_; }
  void seekp(std::uint64_t position) override { position_ = position; }
  const std::vector<char>& bytes() const { return bytes_; }

 private:
  std::vector<char> bytes_;
  std::uint64_t position_ = 0;
};

class MemoryIStream final : public Imf::IStream {
 public:
  MemoryIStream(ByteSpan bytes, const char* name)
      : Imf::IStream(name), bytes_(bytes) {}
  // Throws Iex::InputExc past the end, as OpenEXR's own streams do.
  bool read(char c[], int n) override;
  std::uint64_t tellg() override { return position_; }
  void seekg(std::uint64_t position) override { position_ = position; }

 private:
  ByteSpan bytes_;
  std::uint64_t position_ = 0;
};

}  // namespace clrt::image_detail

// A view of bytes held elsewhere (a file read whole, a rank's received copy), which the decoders
// read in place rather than from a copy of their own.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace clrt {

class ByteSpan {
 public:
  ByteSpan() = default;
  ByteSpan(const std::uint8_t* data, std::size_t size) : data_(data), size_(size) {}
  ByteSpan(const std::vector<std::uint8_t>& bytes) : ByteSpan(bytes.data(), bytes.size()) {}
  explicit ByteSpan(std::string_view text)
      : ByteSpan(reinterpret_cast<const std::uint8_t*>(text.data()), text.size()) {}

  const std::uint8_t* data() const { return data_; }
  std::size_t size() const { return size_; }
  bool empty() const { return size_ == 0; }
  const std::uint8_t* begin() const { return data_; }
  const std::uint8_t* end() const { return data_ + size_; }
  std::uint8_t operator[](std::size_t i) const { return data_[i]; }
  // The first min(n, size) bytes.
  ByteSpan head(std::size_t n) const { return {data_, n < size_ ? n : size_}; }

 private:
  const std::uint8_t* data_ = nullptr;
  std::size_t size_ = 0;
};

// An image file's bytes and the name its errors give it (the path as the user wrote it).
struct ImageBytes {
  ByteSpan bytes;
  std::string name;
};

}  // namespace clrt

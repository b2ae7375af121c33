// File helpers for the image tests: whole-file byte access, the message of an ImageError, and
// the scratch directory to put the files in.
#pragma once

#include <cstdint>
#include <fstream>
#include <functional>
#include <initializer_list>
#include <iterator>
#include <stdexcept>
#include <string>
#include <vector>

#include "image/image.hpp"
#include "scratch_dir.hpp"

namespace clrt::test {

using Bytes = std::vector<std::uint8_t>;

inline Bytes read_bytes(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw std::runtime_error("test cannot open " + path);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

inline void write_bytes(const std::string& path, const Bytes& bytes) {
  std::ofstream out(path, std::ios::binary);
  out.write(reinterpret_cast<const char*>(bytes.data()),
            static_cast<std::streamsize>(bytes.size()));
  if (!out) throw std::runtime_error("test cannot write " + path);
}

inline Bytes concat(std::initializer_list<Bytes> parts) {
  Bytes all;
  for (const auto& part : parts) all.insert(all.end(), part.begin(), part.end());
  return all;
}

inline Bytes bytes_of(const std::string& text) {
  return {text.begin(), text.end()};
}

// The message of the ImageError `step` throws, or "" if it throws none.
inline std::string error_of(const std::function<void()>& step) {
  try {
    step();
  } catch (const ImageError& error) {
    return error.what();
  }
  return {};
}

}  // namespace clrt::test

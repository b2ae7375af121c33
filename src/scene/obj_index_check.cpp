#include "scene/obj_index_check.hpp"

#include <charconv>
#include <sstream>
#include <string_view>
#include <vector>

#include "scene/mesh_loader.hpp"

namespace clrt {
namespace {

std::vector<std::string_view> split(std::string_view line, std::string_view separators) {
  std::vector<std::string_view> parts;
  std::size_t pos = 0;
  while (pos <= line.size()) {
    std::size_t end = line.find_first_of(separators, pos);
    if (end == std::string_view::npos) end = line.size();
    parts.push_back(line.substr(pos, end - pos));
    pos = end + 1;
  }
  return parts;
}

std::vector<std::string_view> words_of(std::string_view line) {
  std::vector<std::string_view> words;
  for (std::string_view part : split(line, " \t\r"))
    if (!part.empty()) words.push_back(part);
  return words;
}

// A positive index may refer to an element defined later in the file, so it is checked only
// once the whole file has been counted.
struct ForwardReference {
  int line;
  long index;
  const char* what;
};

class IndexChecker {
 public:
  explicit IndexChecker(const std::string& path) : path_(path) {}

  void check_line(std::string_view text, int line) {
    const std::vector<std::string_view> words = words_of(text);
    if (words.empty()) return;
    if (words[0] == "v") ++positions_;
    if (words[0] == "vn") ++normals_;
    if (words[0] != "f") return;
    if (words.size() < 4) fail(line, "a face needs at least 3 corners");
    for (std::size_t i = 1; i < words.size(); ++i) check_corner(words[i], line);
  }

  void check_forward_references() const {
    for (const ForwardReference& ref : forward_) {
      const long count = ref.what == kPosition ? positions_ : normals_;
      if (ref.index > count)
        fail(ref.line, std::string(ref.what) + " index " + std::to_string(ref.index) +
                           " is out of range (the file has " + std::to_string(count) + ")");
    }
  }

 private:
  static constexpr const char* kPosition = "vertex";
  static constexpr const char* kNormal = "normal";

  // A corner is v, v/vt, v//vn or v/vt/vn.
  void check_corner(std::string_view corner, int line) {
    const std::vector<std::string_view> parts = split(corner, "/");
    if (parts.size() > 3) fail(line, "bad face corner '" + std::string(corner) + "'");
    check_index(parts[0], corner, kPosition, positions_, line);
    if (parts.size() == 3 && !parts[2].empty())
      check_index(parts[2], corner, kNormal, normals_, line);
  }

  void check_index(std::string_view text, std::string_view corner, const char* what,
                   long count_so_far, int line) {
    long index = 0;
    const auto result = std::from_chars(text.data(), text.data() + text.size(), index);
    if (text.empty() || result.ec != std::errc() || result.ptr != text.data() + text.size())
      fail(line, "bad face corner '" + std::string(corner) + "'");
    if (index == 0) fail(line, std::string(what) + " index 0 is not allowed (indices start at 1)");
    if (index < 0 && count_so_far + index < 0)
      fail(line, "relative " + std::string(what) + " index " + std::to_string(index) +
                     " reaches before the first one");
    if (index > count_so_far) forward_.push_back({line, index, what});
  }

  [[noreturn]] void fail(int line, const std::string& message) const {
    throw MeshError(path_ + ":" + std::to_string(line) + ": " + message);
  }

  std::string path_;
  long positions_ = 0, normals_ = 0;
  std::vector<ForwardReference> forward_;
};

}  // namespace

void check_obj_face_indices(const std::string& text, const std::string& path) {
  IndexChecker checker(path);
  std::istringstream in(text);
  std::string line;
  for (int number = 1; std::getline(in, line); ++number) checker.check_line(line, number);
  checker.check_forward_references();
}

}  // namespace clrt

// Reads numbers out of clrt's --stats=json by key: enough for a benchmark table, with no JSON
// library to install.
#pragma once

#include <cstdlib>
#include <string>
#include <utility>

namespace clrt::bench {

class JsonNumbers {
 public:
  explicit JsonNumbers(std::string text) : text_(std::move(text)) {}
  // The number after the first `"key":`, or 0 when there is none.
  double get(const std::string& key) const {
    const auto at = text_.find("\"" + key + "\":");
    if (at == std::string::npos) return 0;
    return std::strtod(text_.c_str() + at + key.size() + 3, nullptr);
  }

 private:
  std::string text_;
};

}  // namespace clrt::bench

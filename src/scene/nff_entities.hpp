// Groups NFF's lines into entities: NFF writes an entity's numbers on as many lines as it likes
// (`c` on one line or three, `p` one vertex per line), and only entity names and view keywords
// start with something other than a number.
#pragma once

#include <functional>
#include <optional>
#include <string>

#include "scene/lexer.hpp"

namespace clrt {

// Takes the lines one at a time and hands on each entity, as one Line (its name, then every word
// of its own line and of the lines after it that start with a number), once the next entity's
// line or the file's end shows that it is complete: a loader holds one entity's words, not the
// file's.
class NffEntityGrouper {
 public:
  NffEntityGrouper(std::string file, std::function<void(const Line&)> apply)
      : file_(std::move(file)), apply_(std::move(apply)) {}

  // Throws SceneError for a first line that starts with a number.
  void take(Line& line);
  // Hands on the last entity.
  void finish();

 private:
  std::string file_;
  std::function<void(const Line&)> apply_;
  std::optional<Line> entity_;
};

}  // namespace clrt

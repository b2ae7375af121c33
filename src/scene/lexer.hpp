// Splits scene text (.ray or NFF) into lines of words, remembering where each word was written.
#pragma once

#include <functional>
#include <string>
#include <vector>

namespace clrt {

struct Word {
  std::string text;    // without the quotes of a quoted word
  int line = 1;        // 1-based line it was written on
  int column = 1;      // 1-based byte column of the first character (the opening quote if quoted)
  int end_column = 1;  // one past the last character, so "missing word" errors can point there
  bool quoted = false;
};

struct Line {
  int number = 1;           // 1-based
  std::vector<Word> words;  // never empty: blank and comment-only lines are dropped
};

// Words are separated by runs of spaces, tabs and carriage returns (so CRLF files read the same);
// `#` starts a comment that runs to the end of the line. A word that starts with `"` runs to the
// next `"` and may hold spaces and `#` (used for mesh paths). Throws SceneError, located in
// `file`, on an unterminated quote or a line longer than limits::kMaxLineBytes.
std::vector<Line> split_into_lines(const std::string& text, const std::string& file);

// The same lines one at a time, each passed to `take` and dropped after it: a loader that needs
// no line twice holds one line's words, not the file's.
void for_each_line(const std::string& text, const std::string& file,
                   const std::function<void(Line&)>& take);

}  // namespace clrt

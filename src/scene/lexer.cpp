#include "scene/lexer.hpp"

#include <cstddef>
#include <utility>

#include "scene/limits.hpp"
#include "scene/source_location.hpp"

namespace clrt {
namespace {

bool is_separator(char c) { return c == ' ' || c == '\t' || c == '\r'; }

// Reads one word starting at `pos` (not a separator, not `#`); advances `pos` past it.
Word read_word(const std::string& line, std::size_t& pos, int line_number,
               const std::string& file) {
  Word word;
  word.line = line_number;
  word.column = static_cast<int>(pos) + 1;
  if (line[pos] == '"') {
    const std::size_t close = line.find('"', pos + 1);
    if (close == std::string::npos)
      throw SceneError({file, line_number, word.column}, "unterminated quoted word");
    word.text = line.substr(pos + 1, close - pos - 1);
    word.quoted = true;
    pos = close + 1;
  } else {
    const std::size_t start = pos;
    while (pos < line.size() && !is_separator(line[pos]) && line[pos] != '#') ++pos;
    word.text = line.substr(start, pos - start);
  }
  word.end_column = static_cast<int>(pos) + 1;
  return word;
}

std::vector<Word> split_words(const std::string& line, int line_number, const std::string& file) {
  std::vector<Word> words;
  std::size_t pos = 0;
  while (pos < line.size()) {
    if (is_separator(line[pos])) {
      ++pos;
    } else if (line[pos] == '#') {
      break;
    } else {
      words.push_back(read_word(line, pos, line_number, file));
    }
  }
  return words;
}

}  // namespace

void for_each_line(const std::string& text, const std::string& file,
                   const std::function<void(Line&)>& take) {
  int number = 0;
  std::size_t start = 0;
  while (start < text.size()) {
    std::size_t end = text.find('\n', start);
    if (end == std::string::npos) end = text.size();
    ++number;
    if (end - start > limits::kMaxLineBytes)
      throw SceneError({file, number, static_cast<int>(limits::kMaxLineBytes) + 1},
                       "the line is " + std::to_string(end - start) +
                           " bytes long, more than the limit of " +
                           std::to_string(limits::kMaxLineBytes) + "; it starts '" +
                           text.substr(start, limits::kExcerptBytes) + "...'");
    Line line{number, split_words(text.substr(start, end - start), number, file)};
    if (!line.words.empty()) take(line);
    start = end + 1;
  }
}

std::vector<Line> split_into_lines(const std::string& text, const std::string& file) {
  std::vector<Line> lines;
  for_each_line(text, file, [&](Line& line) { lines.push_back(std::move(line)); });
  return lines;
}

}  // namespace clrt

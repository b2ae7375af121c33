#include "scene/nff_entities.hpp"

#include <iterator>

#include "scene/command_args.hpp"
#include "scene/source_location.hpp"

namespace clrt {

std::vector<Line> group_nff_entities(std::vector<Line> lines, const std::string& file) {
  std::vector<Line> entities;
  for (Line& line : lines) {
    const Word& first = line.words.front();
    if (!looks_numeric(first)) {
      entities.push_back(std::move(line));
      continue;
    }
    if (entities.empty())
      throw SceneError(
          {file, first.line, first.column},
          "expected an entity (v, b, l, f, c, s, p or pp), found the number '" + first.text + "'");
    std::vector<Word>& words = entities.back().words;
    words.insert(words.end(), std::make_move_iterator(line.words.begin()),
                 std::make_move_iterator(line.words.end()));
  }
  return entities;
}

}  // namespace clrt

#include "scene/nff_entities.hpp"

#include <iterator>

#include "scene/command_args.hpp"
#include "scene/source_location.hpp"

namespace clrt {

void NffEntityGrouper::take(Line& line) {
  const Word& first = line.words.front();
  if (!looks_numeric(first)) {
    finish();
    entity_ = std::move(line);
    return;
  }
  if (!entity_)
    throw SceneError(
        {file_, first.line, first.column},
        "expected an entity (v, b, l, f, c, s, p or pp), found the number '" + first.text + "'");
  std::vector<Word>& words = entity_->words;
  words.insert(words.end(), std::make_move_iterator(line.words.begin()),
               std::make_move_iterator(line.words.end()));
}

void NffEntityGrouper::finish() {
  if (!entity_) return;
  apply_(*entity_);
  entity_.reset();
}

}  // namespace clrt

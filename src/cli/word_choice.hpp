// The check of an option that takes one of a few words (--tonemap clamp|filmic), worded as the
// other checks word theirs, with the nearest word offered: CLI11's IsMember alone says
// "filmc not in {clamp,filmic}".
#pragma once

#include <CLI/CLI.hpp>

#include <string>
#include <vector>

namespace clrt {

// Accepts any of `words` in any case and writes it back as `words` spells it; anything else is
// "filmc is not one of clamp, filmic (did you mean filmic?)", the suggestion only when a word is
// close (nearest_name). It describes itself as "{clamp,filmic}", as IsMember does, so that
// --help shows the words and the man page and the completion find them. Give it to
// ->transform().
CLI::Validator word_choice(const std::vector<std::string>& words);

}  // namespace clrt

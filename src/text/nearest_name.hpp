// The name a mistyped word was probably meant to be, for "did you mean ...?" in every clrt
// tool's usage errors and the scene reader's errors.
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

namespace clrt {

// Edits that turn `a` into `b`: insertions, deletions, substitutions and swaps of two
// neighbouring characters (the commonest slip of the fingers: --resolutoin) each count one.
std::size_t edit_distance(const std::string& a, const std::string& b);

// The name in `names` nearest to `word`, when it is close enough to be what was meant: at
// most two edits and at most a third of the word's length (one edit always allowed, but
// nothing for a single letter), so that short words are not matched to anything. Ties go to
// the earlier name.
std::optional<std::string> nearest_name(const std::string& word,
                                        const std::vector<std::string>& names);

// "did you mean 'sphere'?" for the name nearest_name finds, or "" when none is close: the
// suggestion of the scene readers' errors and warnings.
std::string did_you_mean(const std::string& word, const std::vector<std::string>& names);

// " (did you mean 'sphere'?)" for such a suggestion, to end a message with; "" for none.
std::string in_parentheses(const std::string& suggestion);

}  // namespace clrt

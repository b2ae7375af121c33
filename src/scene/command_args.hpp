// One command of a scene file (a .ray line, or an NFF entity whose numbers may run over several
// lines): checked access to its arguments and errors located at them.
#pragma once

#include <cstddef>
#include <initializer_list>
#include <string>

#include "math/vec3.hpp"
#include "scene/lexer.hpp"
#include "scene/source_location.hpp"

namespace clrt {

class CommandArgs {
 public:
  // `line.words[0]` is the command word; arguments are numbered from 0 after it. Errors are
  // located at each word's own line.
  CommandArgs(const std::string& file, const Line& line);

  const std::string& name() const { return name_; }  // the command word in lower case
  const Word& command_word() const { return line_.words.front(); }  // as written
  std::size_t count() const { return line_.words.size() - 1; }
  const Word& word(std::size_t i) const { return line_.words[i + 1]; }

  // Throws a wrong-number-of-arguments error unless the arguments from `first` on number one of
  // `allowed` (ascending). Too many: at the first extra word; too few: just past the last word.
  // `subject` names what takes the arguments in the message.
  void require_count(std::initializer_list<std::size_t> allowed, std::size_t first,
                     const std::string& subject) const;
  void require_count(std::initializer_list<std::size_t> allowed) const {
    require_count(allowed, 0, name_);
  }

  double number(std::size_t i) const;
  Vec3 vec3(std::size_t first) const;
  Vec3 nonzero_vec3(std::size_t first, const std::string& what) const;
  // A number that must be a whole number in [min, max].
  int whole_number(std::size_t i, int min, int max, const std::string& what) const;
  // A number that must lie in [lo, hi].
  double number_in(std::size_t i, double lo, double hi, const std::string& what) const;

  SourceLocation command_location() const;
  SceneError error_at(std::size_t i, const std::string& message) const;
  SceneError error_past_end(const std::string& message) const;

 private:
  std::string file_;
  const Line& line_;
  std::string name_;
};

// Command names and keywords are case-insensitive: they are compared in lower case.
std::string lower_case(std::string s);

// Whether `word` is written as a number (finite or not, in range or not): the words that can only
// be arguments, never command names or keywords.
bool looks_numeric(const Word& word);

}  // namespace clrt

// Counts on every tool's command line: decimal whole numbers, and messages that say what is
// wrong with a word.
#include <catch2/catch.hpp>

#include "cli/whole_number.hpp"

using clrt::parse_whole_number;

TEST_CASE("whole numbers are decimal digits with an optional sign", "[cli][words]") {
  CHECK(parse_whole_number("42") == 42);
  CHECK(parse_whole_number("-7") == -7);
  CHECK(parse_whole_number("+7") == 7);
  CHECK(parse_whole_number("010") == 10);
  for (const char* word : {"", "-", "abc", "2.5", "1e3", "0x10", " 4", "4 "}) {
    INFO(word);
    CHECK_FALSE(parse_whole_number(word));
  }
}

TEST_CASE("the check tells a word that is no number from a number out of range",
          "[cli][words]") {
  const CLI::Validator check = clrt::whole_number(1, 16);
  std::string word = "abc";
  CHECK(check(word) == "abc is not a whole number");
  word = "17";
  CHECK(check(word) == "17 is not in the range 1 to 16");
  word = "99999999999999999999";
  CHECK(check(word) == "99999999999999999999 is not in the range 1 to 16");
  word = "010";
  CHECK(check(word).empty());
  CHECK(word == "10");
}

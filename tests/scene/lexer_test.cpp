#include "scene/lexer.hpp"

#include <catch2/catch.hpp>

#include "scene/source_location.hpp"

using clrt::Line;
using clrt::split_into_lines;

namespace {

std::vector<std::string> texts(const Line& line) {
  std::vector<std::string> out;
  for (const auto& w : line.words) out.push_back(w.text);
  return out;
}

std::vector<int> columns(const Line& line) {
  std::vector<int> out;
  for (const auto& w : line.words) out.push_back(w.column);
  return out;
}

}  // namespace

TEST_CASE("words carry their 1-based columns, runs of spaces and tabs separate them", "[lexer]") {
  const auto lines = split_into_lines("eye  1\t\t-2 .5\n", "f");
  REQUIRE(lines.size() == 1);
  CHECK(lines[0].number == 1);
  CHECK(texts(lines[0]) == std::vector<std::string>{"eye", "1", "-2", ".5"});
  // e=1..3, spaces 4-5, '1' at 6, tabs 7-8, '-2' at 9-10, space 11, '.5' at 12-13.
  CHECK(columns(lines[0]) == std::vector<int>{1, 6, 9, 12});
  CHECK(lines[0].words[3].end_column == 14);
}

TEST_CASE("comments and blank lines are dropped but keep the line numbers", "[lexer]") {
  const auto lines = split_into_lines("# header\n\n   \t\nsphere # a ball\nplane#flat\n# end", "f");
  REQUIRE(lines.size() == 2);
  CHECK(lines[0].number == 4);
  CHECK(texts(lines[0]) == std::vector<std::string>{"sphere"});
  CHECK(lines[1].number == 5);
  CHECK(texts(lines[1]) == std::vector<std::string>{"plane"});
}

TEST_CASE("CRLF line ends read like LF", "[lexer]") {
  const auto lines = split_into_lines("fov 45\r\nsphere\r\n\r\nplane", "f");
  REQUIRE(lines.size() == 3);
  CHECK(texts(lines[0]) == std::vector<std::string>{"fov", "45"});
  CHECK(lines[0].words[1].end_column == 7);
  CHECK(lines[1].number == 2);
  CHECK(lines[2].number == 4);
}

TEST_CASE("a quoted word keeps its spaces and # and points at its opening quote", "[lexer]") {
  const auto lines = split_into_lines("mesh  \"my model #2.obj\" x", "f");
  REQUIRE(lines.size() == 1);
  REQUIRE(lines[0].words.size() == 3);
  CHECK(lines[0].words[1].text == "my model #2.obj");
  CHECK(lines[0].words[1].quoted);
  CHECK(lines[0].words[1].column == 7);
  CHECK(lines[0].words[1].end_column == 24);
  CHECK(lines[0].words[2].column == 25);
}

TEST_CASE("an unterminated quote is an error at the quote", "[lexer]") {
  try {
    split_into_lines("sphere\nmesh \"open.obj\n", "s.ray");
    FAIL("no error");
  } catch (const clrt::SceneError& e) {
    CHECK(std::string(e.what()) == "s.ray:2:6: error: unterminated quoted word");
  }
}

#include "scene/number.hpp"

#include <catch2/catch.hpp>

using clrt::NumberProblem;
using clrt::parse_number;

TEST_CASE("decimal floats in all their spellings", "[number]") {
  CHECK(parse_number(".5").value == 0.5);
  CHECK(parse_number("-2").value == -2.0);
  CHECK(parse_number("+3").value == 3.0);
  CHECK(parse_number("1e-3").value == 0.001);
  CHECK(parse_number("2.5E2").value == 250.0);
  CHECK(parse_number("7.").value == 7.0);
  CHECK(parse_number("-.25e+1").value == -2.5);
  CHECK(parse_number("0.577350269").value == 0.577350269);
  CHECK(parse_number("0").problem == NumberProblem::None);
}

TEST_CASE("words that are not entirely a decimal number are rejected", "[number]") {
  for (const char* word : {"", "abc", "1.2.3", "1e", "e5", ".", "-", "+-1", "1,5", "0x10", "1f",
                           "3 ", " 3", "--1", "1e+", "point"}) {
    INFO(word);
    CHECK(parse_number(word).problem == NumberProblem::NotANumber);
  }
}

TEST_CASE("NaN and infinity spellings are not finite numbers", "[number]") {
  for (const char* word : {"nan", "NaN", "-nan", "inf", "+Inf", "-INFINITY", "infinity"}) {
    INFO(word);
    CHECK(parse_number(word).problem == NumberProblem::NotFinite);
  }
}

TEST_CASE("literals beyond the range of a double are rejected", "[number]") {
  CHECK(parse_number("1e999").problem == NumberProblem::OutOfRange);
  CHECK(parse_number("-1e400").problem == NumberProblem::OutOfRange);
}

TEST_CASE("literals beyond the scene limit of 1e12 are too large", "[number][limits]") {
  CHECK(parse_number("1e12").problem == NumberProblem::None);
  CHECK(parse_number("-1e12").problem == NumberProblem::None);
  CHECK(parse_number("1.000001e12").problem == NumberProblem::TooLarge);
  CHECK(parse_number("-1e13").problem == NumberProblem::TooLarge);
  CHECK(parse_number("1e308").problem == NumberProblem::TooLarge);
  CHECK(parse_number("1e-300").problem == NumberProblem::None);
}

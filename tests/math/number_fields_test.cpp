// read_number_fields against std::regex, the reader it replaced: the same texts match, with the
// same numbers, over hand-picked edge cases and random texts near each form.
#include <catch2/catch.hpp>

#include <random>
#include <regex>
#include <string>

#include "math/number_fields.hpp"

using clrt::NumberForm;
using clrt::read_number_fields;

namespace {

struct FormCase {
  NumberForm form;
  std::regex reference;
};

std::vector<FormCase> form_cases() {
  const std::string n = "(0|[1-9][0-9]{0,9})";
  return {
      {{"#x#", 6, false, true}, std::regex("([0-9]{1,6})[xX]([0-9]{1,6})")},
      {{"#:#", 10}, std::regex("([0-9]{1,10}):([0-9]{1,10})")},
      {{"#,# #x# of #x#", 10, true}, std::regex(n + "," + n + " " + n + "x" + n + " of " + n + "x" + n)},
  };
}

void check_same(const FormCase& c, const std::string& text) {
  INFO("form " << c.form.pattern << ", text \"" << text << "\"");
  std::smatch m;
  const bool expected = std::regex_match(text, m, c.reference);
  const auto numbers = read_number_fields(text, c.form);
  REQUIRE(numbers.has_value() == expected);
  if (!expected) return;
  REQUIRE(numbers->size() + 1 == m.size());
  for (std::size_t i = 0; i < numbers->size(); ++i) CHECK((*numbers)[i] == std::stoull(m[i + 1].str()));
}

}  // namespace

TEST_CASE("number fields match what the regular expressions matched", "[math][text]") {
  const std::vector<FormCase> cases = form_cases();
  for (const std::string text : {"640x480", "640X480", "640x", "x480", "1234567x1", "123456x123456",
                                 "0x0", "007x1", " 1x1", "1x1 ", "1:24", "1:", ":1", "1234567890:1",
                                 "12345678901:1", "1;2", "0,0 32x32 of 64x64", "00,0 32x32 of 64x64",
                                 "0,0 32X32 of 64x64", "0,0 32x32 of 64x6", "0,0 32x32 0f 64x64",
                                 "9999999999,0 1x1 of 1x1", "10000000000,0 1x1 of 1x1", ""})
    for (const FormCase& c : cases) check_same(c, text);
}

TEST_CASE("random texts near each form read as the regular expressions read them", "[math][text]") {
  std::mt19937 random(7);
  const std::string alphabet = "0123456789xX:, of";
  for (const FormCase& c : form_cases()) {
    for (int trial = 0; trial < 20000; ++trial) {
      // Built from the form, then bent: digits of random length, a character changed or not.
      std::string text;
      for (const char p : c.form.pattern) {
        if (p != '#') {
          text += p;
          continue;
        }
        const int digits = static_cast<int>(random() % 13);
        for (int d = 0; d < digits; ++d) text += static_cast<char>('0' + random() % 10);
      }
      if (!text.empty() && random() % 3 == 0) text[random() % text.size()] = alphabet[random() % alphabet.size()];
      check_same(c, text);
    }
  }
}

// The option-value parsers every numeric option goes through: whole text or nothing, one sign at
// most, the promised count of numbers with the part that is wrong named.
#include "marker/cli/option_values.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "base/error.hpp"

namespace mark::cli {
namespace {

TEST(OptionValues, NumbersAreTheWholeText) {
  EXPECT_EQ(parse_number("1e-3"), 1e-3);
  EXPECT_EQ(parse_number("-2.5"), -2.5);
  EXPECT_FALSE(parse_number(""));
  EXPECT_FALSE(parse_number("5mm"));
  EXPECT_FALSE(parse_number("1,5"));
  EXPECT_TRUE(std::isinf(*parse_number("1e400")));  // a number, refused by the range check
}

TEST(OptionValues, WholeNumbersHaveOneSignAndNoFraction) {
  EXPECT_EQ(parse_whole_number("42"), 42);
  EXPECT_EQ(parse_whole_number("+42"), 42);
  EXPECT_EQ(parse_whole_number("-42"), -42);
  EXPECT_EQ(parse_whole_number("9223372036854775807"), INT64_MAX);
  for (const char* bad : {"", "+", "-", "+-13", "-+13", "1.0", "1e3", " 1", "1 ", "9223372036854775808"})
    EXPECT_FALSE(parse_whole_number(bad)) << bad;  // "+-13" was found by fuzz_option_values
}

TEST(OptionValues, ListsHoldTheirCountAndNameTheWrongPart) {
  EXPECT_EQ(parse_numbers("--circle", "1,-2,3.5", ",", 3, "CX,CY,R"), (std::vector<double>{1, -2, 3.5}));
  EXPECT_EQ(parse_numbers("--window", "63X38", "xX", 2, "WxH"), (std::vector<double>{63, 38}));
  auto error = [](std::string_view text) {
    try {
      parse_numbers("--circle", text, ",", 3, "CX,CY,R");
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string("(accepted)");
  };
  EXPECT_EQ(error("1,2"), "--circle '1,2': expected CX,CY,R");
  EXPECT_EQ(error("1,2,3,4"), "--circle '1,2,3,4': expected CX,CY,R");
  EXPECT_EQ(error("1,,3"), "--circle '1,,3': expected CX,CY,R");
  EXPECT_EQ(error("1,two,3"), "--circle '1,two,3': 'two' is not a number");
}

}  // namespace
}  // namespace mark::cli

// Check characters against the examples their standards and registries publish, and the
// templates that compute them: each check covers the text before it, separators skipped; a
// character the algorithm cannot take is an error naming it, never a wrong check.
#include "marker/vars/check_digit.hpp"

#include <gtest/gtest.h>

#include "base/error.hpp"
#include "marker/vars/render.hpp"

namespace mark {
namespace {

TEST(CheckDigit, PublishedExamples) {
  // Luhn: the ISO/IEC 7812-1 worked example "7992739871" + 3.
  EXPECT_EQ(check_character(CheckDigit::luhn, "7992739871"), '3');
  // A card number in its printed groups: 4539 1488 0343 6467 (a valid Luhn test number).
  EXPECT_EQ(check_character(CheckDigit::luhn, "4539 1488 0343 646"), '7');
  // GS1 mod 10: EAN-13 4006381333931, GTIN-12 036000291452.
  EXPECT_EQ(check_character(CheckDigit::mod10, "400638133393"), '1');
  EXPECT_EQ(check_character(CheckDigit::mod10, "03600029145"), '2');
  // Mod 11, ISBN-10 weights: 0-306-40615-2 and 0-8044-2957-X.
  EXPECT_EQ(check_character(CheckDigit::mod11, "0-306-40615"), '2');
  EXPECT_EQ(check_character(CheckDigit::mod11, "0-8044-2957"), 'X');
  // ISO 7064 MOD 11-2: ORCID 0000-0002-1825-0097 and 0000-0002-1694-233X.
  EXPECT_EQ(check_character(CheckDigit::iso7064_11_2, "0000-0002-1825-009"), '7');
  EXPECT_EQ(check_character(CheckDigit::iso7064_11_2, "0000-0002-1694-233"), 'X');
  // ISO 7064 MOD 37,36: the GRid example A1-2425G-ABC1234002-M.
  EXPECT_EQ(check_character(CheckDigit::iso7064_37_36, "A1-2425G-ABC1234002"), 'M');
  // VIN: 1M8GDM9AXKP042788 (49 CFR 565's example) and 11111111111111111 (check 1).
  EXPECT_EQ(check_character(CheckDigit::vin, "1M8GDM9A", "KP042788"), 'X');
  EXPECT_EQ(check_character(CheckDigit::vin, "11111111", "11111111"), '1');
}

TEST(CheckDigit, ACharacterTheAlgorithmCannotTakeIsNamed) {
  try {
    check_character(CheckDigit::luhn, "SN 42");
    FAIL() << "a letter passed the Luhn check";
  } catch (const InputError& e) {
    EXPECT_STREQ(e.what(), "{check:luhn}: 'S' at character 1 of \"SN 42\" is not a digit");
  }
  EXPECT_THROW(check_character(CheckDigit::vin, "1M8GDM9A", "KP04278O"), InputError);  // O is not a VIN character
  EXPECT_THROW(check_character(CheckDigit::vin, "1M8GDM9", "KP042788"), InputError);   // 16 characters
  EXPECT_THROW(check_character(CheckDigit::mod10, " - "), InputError);                 // nothing to check
  EXPECT_EQ(parse_check_digit("iso7064-37-36"), CheckDigit::iso7064_37_36);
  EXPECT_FALSE(parse_check_digit("crc32"));
}

TEST(CheckDigit, TemplatesPutTheCheckWhereTheFieldStands) {
  std::map<std::string, CounterSpec> counters{{"sn", CounterSpec{}}};
  counters["sn"].width = 6;
  std::map<std::string, std::int64_t> serials{{"sn", 41}};
  MarkValues v;
  v.counters = &counters;
  v.serials = &serials;
  // GTIN-13 of prefix 400638 and serial 133393: its check ends it.
  EXPECT_EQ(render(TextTemplate::parse("400638{sn:6}{check:mod10}", "t"), v), "4006380000414");
  EXPECT_EQ(render(TextTemplate::parse("4006381333{check:mod10}", "t"), v), "40063813339");
  // The VIN check at position 9, over the characters after it too.
  EXPECT_EQ(render(TextTemplate::parse("1M8GDM9A{check:vin}KP042788", "t"), v), "1M8GDM9AXKP042788");
  // A second check covers only what follows the first.
  EXPECT_EQ(render(TextTemplate::parse("7992739871{check:luhn} 030640615{check:mod11}", "t"), v),
            "79927398713 0306406152");
  EXPECT_THROW(TextTemplate::parse("{sn}{check:crc}", "t"), InputError);
}

}  // namespace
}  // namespace mark

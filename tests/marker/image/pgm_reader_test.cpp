// The PGM reader: both encodings, comments, 16-bit samples, and a clear error — never a crash
// or a huge allocation — for every malformed or truncated file, including random corruption.
#include <gtest/gtest.h>

#include <random>
#include <string>

#include "base/error.hpp"
#include "marker/image/gray_image.hpp"

namespace mark::test {
namespace {

std::string pgm_error_of(const std::string& bytes) {
  try {
    parse_pgm(bytes, "t.pgm");
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST(PgmReader, ReadsAsciiWithComments) {
  const GrayImage img = parse_pgm("P2\n# a comment\n3 2 # width height\n10\n0 5 10\n10 5 0\n", "a.pgm");
  ASSERT_EQ(img.width, 3);
  ASSERT_EQ(img.height, 2);
  EXPECT_FLOAT_EQ(img.at(1, 0), 0.5f);
  EXPECT_FLOAT_EQ(img.at(0, 1), 1.0f);
}

TEST(PgmReader, ReadsBinary8And16Bit) {
  const std::string b8 = std::string("P5 2 1 255\n") + '\x00' + '\xff';
  const GrayImage a = parse_pgm(b8, "b8.pgm");
  EXPECT_FLOAT_EQ(a.at(0, 0), 0.0f);
  EXPECT_FLOAT_EQ(a.at(1, 0), 1.0f);
  const std::string b16 = std::string("P5\n2 1\n1000\n") + '\x01' + '\xf4' + '\x03' + '\xe8';
  const GrayImage b = parse_pgm(b16, "b16.pgm");
  EXPECT_FLOAT_EQ(b.at(0, 0), 0.5f);
  EXPECT_FLOAT_EQ(b.at(1, 0), 1.0f);
}

TEST(PgmReader, NamesTheFileAndPlaceOfEachError) {
  EXPECT_NE(pgm_error_of("P6 1 1 255\nabc").find("not a PGM"), std::string::npos);
  EXPECT_NE(pgm_error_of("P5 0 4 255\n").find("at least 1"), std::string::npos);
  EXPECT_NE(pgm_error_of("P5 100000 100000 255\n").find("larger than"), std::string::npos);
  EXPECT_NE(pgm_error_of("P5 2 2 0\n").find("maximum value"), std::string::npos);
  EXPECT_NE(pgm_error_of("P5 2 2 255\nab").find("truncated"), std::string::npos);
  EXPECT_NE(pgm_error_of("P2 2 1 9\n3 12\n").find("exceeds"), std::string::npos);
  EXPECT_NE(pgm_error_of("P2 2 1 9\n3 x\n").find("found 'x'"), std::string::npos);
  EXPECT_NE(pgm_error_of("P2 2 1 9\n3").find("file ends"), std::string::npos);
  EXPECT_NE(pgm_error_of("P5 1 1 255").find("whitespace"), std::string::npos);
  EXPECT_NE(pgm_error_of("P5 12345678901 1 255\n").find("too large"), std::string::npos);
  const std::string e = pgm_error_of("P5 2 2 255\nab");
  EXPECT_EQ(e.rfind("t.pgm: PGM byte ", 0), 0u) << e;
}

TEST(PgmReader, RandomCorruptionNeverCrashes) {
  std::string good = "P2\n# c\n4 3\n255\n";
  for (int i = 0; i < 12; ++i) good += std::to_string(i * 20) + " ";
  const std::string bin = std::string("P5\n4 3\n255\n") + std::string(12, '\x40');
  std::mt19937 rng(1);
  int parsed = 0, refused = 0;
  for (const std::string& base : {good, bin})
    for (int trial = 0; trial < 3000; ++trial) {
      std::string s = base;
      const int edits = 1 + static_cast<int>(rng() % 4);
      for (int k = 0; k < edits; ++k) {
        const std::size_t at = rng() % s.size();
        switch (rng() % 3) {
          case 0: s[at] = static_cast<char>(rng() % 256); break;
          case 1: s.erase(at, 1 + rng() % 3); break;
          default: s.insert(s.begin() + static_cast<std::ptrdiff_t>(at), "0123456789 #\nP5-"[rng() % 16]); break;
        }
        if (s.empty()) s.push_back('P');
      }
      try {
        const GrayImage img = parse_pgm(s, "fuzz.pgm");
        EXPECT_EQ(img.pixels.size(), static_cast<std::size_t>(img.width) * img.height);
        ++parsed;
      } catch (const InputError&) {
        ++refused;
      }
    }
  EXPECT_GT(parsed, 0);
  EXPECT_GT(refused, 0);
}

}  // namespace
}  // namespace mark::test

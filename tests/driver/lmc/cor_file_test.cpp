// EzCad correction files in both formats, built byte by byte here: the 65 × 65 deltas as the
// board's sign-magnitude words, the lens scale, and refusals that name the entry and the value.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>

#include "driver/lmc/codec.hpp"
#include "driver/lmc/cor_file.hpp"

namespace mark::lmc {
namespace {

void put_f64(std::vector<std::uint8_t>& b, std::size_t at, double v) { std::memcpy(b.data() + at, &v, 8); }
void put_i32(std::vector<std::uint8_t>& b, std::size_t at, std::int32_t v) { std::memcpy(b.data() + at, &v, 4); }

// A delta pattern with both signs and a range of magnitudes.
double dx_of(std::size_t i) { return double(int(i % 129) - 64) * 13.0; }
double dy_of(std::size_t i) { return double(int(i / 65) - 32) * -7.0; }

std::vector<std::uint8_t> legacy_file(double scale) {
  std::vector<std::uint8_t> b(0x24 + kCorEntries * 8, 0);
  std::memcpy(b.data(), "JCZ-COR legacy", 14);
  put_f64(b, 0x1C, scale);
  for (std::size_t i = 0; i < kCorEntries; ++i) {
    put_i32(b, 0x24 + 8 * i, std::int32_t(dx_of(i)));
    put_i32(b, 0x24 + 8 * i + 4, std::int32_t(dy_of(i)));
  }
  return b;
}

std::vector<std::uint8_t> lmc1cor_file(double scale) {
  std::vector<std::uint8_t> b(0x210 + kCorEntries * 16, 0);
  const char* label = "LMC1COR_1.0";
  for (int i = 0; i < 11; ++i) b[2 * std::size_t(i)] = std::uint8_t(label[i]);
  put_f64(b, 0x18 + 43 * 8, scale);
  for (std::size_t i = 0; i < kCorEntries; ++i) {
    put_f64(b, 0x210 + 16 * i, dx_of(i) + 0.3);  // rounded to the nearest unit
    put_f64(b, 0x210 + 16 * i + 8, dy_of(i) - 0.3);
  }
  return b;
}

void expect_pattern(const CorrectionTable& t) {
  ASSERT_EQ(t.entries.size(), kCorEntries);
  for (std::size_t i = 0; i < kCorEntries; ++i) {
    ASSERT_EQ(decode_cor_delta(t.entries[i][0]), std::int32_t(dx_of(i))) << i;
    ASSERT_EQ(decode_cor_delta(t.entries[i][1]), std::int32_t(dy_of(i))) << i;
  }
  EXPECT_EQ(t.entries[0][0], encode_cor_delta(-64 * 13));
  EXPECT_EQ(t.entries[0][0], 0x8000 + 832);
}

std::string cor_error_of(std::span<const std::uint8_t> b) {
  try {
    parse_cor(b, "lens.cor");
  } catch (const CorFileError& e) {
    return e.what();
  }
  return "";
}

TEST(LmcCorFile, LegacyIntFormat) {
  const CorrectionTable t = parse_cor(legacy_file(595.77), "legacy.cor");
  EXPECT_EQ(t.format, CorrectionTable::Format::legacy_int);
  EXPECT_DOUBLE_EQ(t.scale, 595.77);
  expect_pattern(t);
}

TEST(LmcCorFile, Lmc1CorFloatFormat) {
  const CorrectionTable t = parse_cor(lmc1cor_file(600.5), "float.cor");
  EXPECT_EQ(t.format, CorrectionTable::Format::lmc1cor_float);
  EXPECT_DOUBLE_EQ(t.scale, 600.5);
  expect_pattern(t);
}

TEST(LmcCorFile, ReadsFromDiskAndRefusesWhatDoesNotFit) {
  const auto path = std::filesystem::temp_directory_path() / ("lmc_cor_" + std::to_string(::getpid()) + ".cor");
  {
    const auto b = lmc1cor_file(1);
    std::ofstream(path, std::ios::binary).write(reinterpret_cast<const char*>(b.data()), std::streamsize(b.size()));
  }
  expect_pattern(read_cor_file(path.string()));
  std::filesystem::remove(path);
  EXPECT_THROW(read_cor_file(path.string()), CorFileError);
  // A directory or an endless device: one line naming it, not a raw stream error or bad_alloc.
  for (const auto& [bad, why] : {std::pair{"/tmp", "/tmp: cannot read the correction file: it is a directory"},
                                 {"/dev/zero", "/dev/zero: cannot read the correction file: longer than 1 MiB, the most a "
                                               "correction file may be"}}) {
    try {
      read_cor_file(bad);
      ADD_FAILURE() << bad << " accepted";
    } catch (const CorFileError& e) {
      EXPECT_STREQ(e.what(), why);
    }
  }

  auto b = legacy_file(1);
  b.resize(b.size() - 1);
  EXPECT_NE(cor_error_of(b).find("lens.cor: a legacy (int32) correction file needs 33836 bytes, this one has 33835"),
            std::string::npos)
      << cor_error_of(b);
  b = legacy_file(1);
  put_i32(b, 0x24 + 8 * 100 + 4, 40000);
  EXPECT_NE(cor_error_of(b).find("correction entry 100 (row 1, column 35) dy = 40000 does not fit"),
            std::string::npos)
      << cor_error_of(b);
  b = lmc1cor_file(1);
  put_f64(b, 0x210, std::numeric_limits<double>::quiet_NaN());
  EXPECT_NE(cor_error_of(b).find("correction entry 0 (row 0, column 0) dx = nan"), std::string::npos) << cor_error_of(b);
  b = lmc1cor_file(1);
  b.resize(0x300);
  EXPECT_NE(cor_error_of(b).find("an LMC1COR_1.0 correction file needs 68128 bytes, this one has 768"), std::string::npos) << cor_error_of(b);
  EXPECT_NE(cor_error_of({}).find("needs"), std::string::npos);
}

}  // namespace
}  // namespace mark::lmc

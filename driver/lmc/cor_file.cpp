#include "driver/lmc/cor_file.hpp"

#include <cmath>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <iterator>

#include "base/input_file.hpp"
#include "driver/lmc/codec.hpp"

namespace mark::lmc {
namespace {

constexpr std::size_t kLabelBytes = 0x16;
constexpr std::size_t kFloatTable = 0x210, kFloatScale = 0x18 + 43 * 8;
constexpr std::size_t kIntTable = 0x24, kIntScale = 0x1C;

double f64(const std::uint8_t* p) {
  double v;
  std::memcpy(&v, p, 8);  // little-endian hosts only, as the file (x86 EzCad)
  return v;
}
std::int32_t i32(const std::uint8_t* p) {
  return static_cast<std::int32_t>(std::uint32_t(p[0]) | std::uint32_t(p[1]) << 8 |
                                   std::uint32_t(p[2]) << 16 | std::uint32_t(p[3]) << 24);
}

bool has_lmc1cor_label(std::span<const std::uint8_t> b) {
  static const char label[] = "LMC1COR_1.0";
  if (b.size() < kLabelBytes) return false;
  for (std::size_t i = 0; i < 11; ++i)
    if (b[2 * i] != std::uint8_t(label[i]) || b[2 * i + 1] != 0) return false;
  return true;
}

[[noreturn]] void bad(const std::string& source, const std::string& what) {
  throw CorFileError(source + ": " + what);
}

std::uint16_t delta_word(double v, const std::string& source, std::size_t entry, char axis) {
  if (!std::isfinite(v) || std::abs(std::round(v)) > 32767) {
    char buf[160];
    std::snprintf(buf, sizeof buf,
                  "correction entry %zu (row %zu, column %zu) d%c = %g does not fit the board's "
                  "word (allowed -32767 .. 32767 units)",
                  entry, entry / kCorGrid, entry % kCorGrid, axis, v);
    bad(source, buf);
  }
  return encode_cor_delta(std::llround(v));
}

}  // namespace

CorrectionTable parse_cor(std::span<const std::uint8_t> b, const std::string& source) {
  CorrectionTable t;
  t.source = source;
  std::size_t table, pair_bytes;
  if (has_lmc1cor_label(b)) {
    t.format = CorrectionTable::Format::lmc1cor_float;
    table = kFloatTable, pair_bytes = 16;
  } else {
    t.format = CorrectionTable::Format::legacy_int;
    table = kIntTable, pair_bytes = 8;
  }
  const std::size_t need = table + kCorEntries * pair_bytes;
  if (b.size() < need)
 bad(source, std::string(t.format == CorrectionTable::Format::lmc1cor_float
                                ? "an LMC1COR_1.0"
                                : "a legacy (int32)") +
                    " correction file needs " + std::to_string(need) + " bytes, this one has " +
                    std::to_string(b.size()));
  t.scale = f64(b.data() + (table == kFloatTable ? kFloatScale : kIntScale));
  t.entries.resize(kCorEntries);
  for (std::size_t i = 0; i < kCorEntries; ++i) {
    const std::uint8_t* p = b.data() + table + i * pair_bytes;
    double dx, dy;
    if (pair_bytes == 16) dx = f64(p), dy = f64(p + 8);
    else dx = i32(p), dy = i32(p + 4);
    t.entries[i] = {delta_word(dx, source, i, 'x'), delta_word(dy, source, i, 'y')};
  }
  return t;
}

void check_cor_lens(const CorrectionTable& t, double field_mm) {
  const double lens = t.lens_mm();
  char buf[320];
  if (!(lens > 0) || !std::isfinite(lens)) {
    std::snprintf(buf, sizeof buf,
                  "its lens scale %g units/mm gives no lens size (65536 / scale); the field is %g mm",
                  t.scale, field_mm);
    bad(t.source, buf);
  }
  if (std::abs(lens - field_mm) > kCorLensTolerance * field_mm) {
    std::snprintf(buf, sizeof buf,
                  "made for a %.3f mm lens (scale %.4f units/mm), but the lens field is %g mm: set "
                  "the field to %.3f mm or use a correction file for this lens",
                  lens, t.scale, field_mm, lens);
    bad(t.source, buf);
  }
}

CorrectionTable read_cor_file(const std::string& path) {
  std::string text;
  try {
    text = read_input_file(path, "correction file", 1u << 20);
  } catch (const InputError& e) {
    throw CorFileError(e.what());
  }
  return parse_cor(std::vector<std::uint8_t>(text.begin(), text.end()), path);
}

}  // namespace mark::lmc

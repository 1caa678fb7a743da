// The module maps a verifier grades with, checked against Reed–Solomon itself: the codewords
// read out of zint's symbols through the map must be valid RS codewords block by block (every
// syndrome zero, in the symbology's field and generator) — which no wrong placement, block
// assignment or interleaving passes. Every Data Matrix size (the 144 × 144 included), and QR
// versions 1–40 at every error-correction level (with the data unmasked by the mask the format
// information names).
#include <gtest/gtest.h>

#include <array>
#include <set>

#include "marker/codes/code_spec.hpp"
#include "marker/codes/symbol_map.hpp"
#include "tests/marker/param_print.hpp"

namespace mark {
namespace {

// GF(256) with the given primitive polynomial.
struct Field {
  std::array<int, 512> exp{};
  std::array<int, 256> log{};
  explicit Field(int poly) {
    int x = 1;
    for (int i = 0; i < 255; ++i) {
      exp[i] = x;
      log[x] = i;
      x <<= 1;
      if (x & 0x100) x ^= poly;
    }
    for (int i = 255; i < 512; ++i) exp[i] = exp[i - 255];
  }
  int mul(int a, int b) const { return a && b ? exp[log[a] + log[b]] : 0; }
};

// Syndromes of a block (first codeword the highest power) at α^first … α^(first + ec − 1).
bool syndromes_vanish(const Field& f, const std::vector<int>& block, int ec, int first) {
  for (int j = 0; j < ec; ++j) {
    const int root = f.exp[(j + first) % 255];
    int s = 0;
    for (int c : block) s = f.mul(s, root) ^ c;
    if (s) return false;
  }
  return true;
}

// The codewords read through the map, per block: data first, then error correction, each in
// stream order.
std::vector<std::vector<int>> blocks_of(const SymbolMap& m, const std::vector<int>& stream) {
  int data = 0;
  for (const RsBlock& b : m.blocks) data += b.data;
  std::vector<std::vector<int>> out(m.blocks.size());
  for (int pass = 0; pass < 2; ++pass)
    for (int k = 0; k < m.codewords(); ++k)
      if ((k < data) == (pass == 0)) out[static_cast<std::size_t>(m.block_of[static_cast<std::size_t>(k)])].push_back(stream[static_cast<std::size_t>(k)]);
  return out;
}

// The stream of codewords from the modules; `unmask` flips data modules first.
std::vector<int> read_stream(const SymbolMap& m, const ModuleMatrix& matrix, const std::function<bool(int, int)>& unmask) {
  std::vector<int> stream(static_cast<std::size_t>(m.codewords()), 0);
  std::vector<int> bits(stream.size(), 0);
  for (int r = 0; r < m.rows; ++r)
    for (int c = 0; c < m.cols; ++c) {
      const int k = m.codeword_at(r, c);
      if (k < 0) continue;
      const bool dark = matrix.dark(r, c) != (unmask && unmask(r, c));
      stream[static_cast<std::size_t>(k)] |= dark << m.bit[static_cast<std::size_t>(r) * m.cols + c];
      ++bits[static_cast<std::size_t>(k)];
    }
  for (int b : bits) EXPECT_EQ(b, 8) << "every codeword has eight modules";
  return stream;
}

class DataMatrixMap : public testing::TestWithParam<MatrixSize> {};
TEST_P(DataMatrixMap, ReadsValidReedSolomonBlocks) {
  const MatrixSize s = GetParam();
  CodeSpec spec;
  spec.data = s.rows * s.cols < 256 ? "SN42" : "SN 2026-000123";
  spec.matrix_rows = s.rows;
  spec.matrix_cols = s.cols;
  if (s.rows >= 52) spec.data = std::string(static_cast<std::size_t>(s.rows * 4), 'A');  // several blocks filled
  const ModuleMatrix matrix = encode_code(spec);
  const SymbolMap m = datamatrix_map(s.rows, s.cols);
  static const Field f(0x12D);  // ISO/IEC 16022: x⁸ + x⁵ + x³ + x² + 1, generator roots α¹ … α^n
  const auto blocks = blocks_of(m, read_stream(m, matrix, nullptr));
  for (std::size_t b = 0; b < blocks.size(); ++b) {
    EXPECT_EQ(static_cast<int>(blocks[b].size()), m.blocks[b].data + m.blocks[b].ec);
    EXPECT_TRUE(syndromes_vanish(f, blocks[b], m.blocks[b].ec, 1)) << "block " << b;
  }
  // The fixed patterns as ISO/IEC 16022 draws them: the L solid, the clock tracks alternating.
  for (int r = 0; r < s.rows; ++r) EXPECT_TRUE(matrix.dark(r, 0));
  for (int c = 0; c < s.cols; ++c) EXPECT_TRUE(matrix.dark(s.rows - 1, c));
  for (int c = 0; c < s.cols; ++c) EXPECT_EQ(matrix.dark(0, c), c % 2 == 0);
}
INSTANTIATE_TEST_SUITE_P(EverySize, DataMatrixMap, testing::ValuesIn(datamatrix_sizes()),
                         [](const auto& info) {
                           return std::to_string(info.param.rows) + "x" + std::to_string(info.param.cols);
                         });

bool qr_mask(int mask, int i, int j) {
  switch (mask) {
    case 0: return (i + j) % 2 == 0;
    case 1: return i % 2 == 0;
    case 2: return j % 3 == 0;
    case 3: return (i + j) % 3 == 0;
    case 4: return (i / 2 + j / 3) % 2 == 0;
    case 5: return (i * j) % 2 + (i * j) % 3 == 0;
    case 6: return ((i * j) % 2 + (i * j) % 3) % 2 == 0;
    default: return ((i + j) % 2 + (i * j) % 3) % 2 == 0;
  }
}

TEST(QrMap, ReadsValidReedSolomonBlocksAtEveryVersionAndLevel) {
  static const Field f(0x11D);  // ISO/IEC 18004: x⁸ + x⁴ + x³ + x² + 1, generator roots α⁰ … α^(n−1)
  for (char level : {'L', 'M', 'Q', 'H'})
    for (int version = 1; version <= 40; ++version) {
      SCOPED_TRACE(std::string(1, level) + " version " + std::to_string(version));
      CodeSpec spec;
      spec.symbology = Symbology::qr;
      spec.data = "SN42";
      spec.qr_ecc = level;
      spec.qr_version = version;
      const ModuleMatrix matrix = encode_code(spec);
      ASSERT_EQ(matrix.rows, 17 + 4 * version);
      char ecc = 0;
      int mask = -1;
      qr_format(matrix, ecc, mask);
      // zint may raise the level where the version has room; the format information says which.
      EXPECT_GE(std::string("LMQH").find(ecc), std::string("LMQH").find(level));
      const SymbolMap m = qr_map(version, ecc);
      const auto blocks = blocks_of(m, read_stream(m, matrix, [&](int r, int c) { return qr_mask(mask, r, c); }));
      for (std::size_t b = 0; b < blocks.size(); ++b)
        EXPECT_TRUE(syndromes_vanish(f, blocks[b], m.blocks[b].ec, 0)) << "block " << b;
    }
}

TEST(QrMap, FunctionPatternsAreWhereTheStandardPutsThem) {
  const SymbolMap m = qr_map(7, 'M');
  const int n = m.rows;
  // 45 × 45: three 8 × 8 finder corners, timing row and column, six alignment patterns of 25,
  // 2 × 15 + 1 format modules and 2 × 18 version modules; the rest carries 196 codewords' bits
  // and 0 remainder bits.
  int data = 0;
  for (int k : m.codeword) data += k >= 0;
  EXPECT_EQ(data, 196 * 8);
  EXPECT_EQ(m.codeword_at(0, 0), -1);
  EXPECT_EQ(m.codeword_at(n - 8, 8), -1);  // the dark module
  EXPECT_EQ(m.codeword_at(n - 1, n - 1), 0);  // the first bit starts at the lower right
  EXPECT_EQ(m.bit[static_cast<std::size_t>(n - 1) * n + n - 1], 7);
  std::set<std::string> names;
  for (const PatternSegment& s : m.segments) names.insert(s.name);
  EXPECT_EQ(names, (std::set<std::string>{"A1", "A2", "A3", "B1", "B2", "C"}));
}

}  // namespace
}  // namespace mark

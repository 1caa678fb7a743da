// QR (ISO/IEC 18004): the function patterns (finders with their separators, timing patterns,
// alignment patterns, format and version information, the dark module), the data modules in
// the two-column zig-zag from the lower right, skipping the vertical timing column, and the
// codeword stream interleaved from the blocks (data of every block column by column, then their
// error correction). Block counts and data codewords per version and level are ISO/IEC 18004's
// Table 9 (as zint 2.11 carries it); the misdecode-protection codewords p of its footnote.
#include <algorithm>
#include <array>
#include <bit>
#include <string_view>

#include "base/error.hpp"
#include "marker/codes/symbol_map.hpp"

namespace mark {
namespace {

// Table 9: data codewords, blocks per level (L, M, Q, H), and all codewords, versions 1–40.
constexpr std::array<std::array<short, 40>, 4> kDataCodewords{{
    {19, 34, 55, 80, 108, 136, 156, 194, 232, 274, 324, 370, 428, 461, 523, 589, 647, 721, 795, 861,
     932, 1006, 1094, 1174, 1276, 1370, 1468, 1531, 1631, 1735, 1843, 1955, 2071, 2191, 2306, 2434, 2566, 2702, 2812, 2956},
    {16, 28, 44, 64, 86, 108, 124, 154, 182, 216, 254, 290, 334, 365, 415, 453, 507, 563, 627, 669,
     714, 782, 860, 914, 1000, 1062, 1128, 1193, 1267, 1373, 1455, 1541, 1631, 1725, 1812, 1914, 1992, 2102, 2216, 2334},
    {13, 22, 34, 48, 62, 76, 88, 110, 132, 154, 180, 206, 244, 261, 295, 325, 367, 397, 445, 485,
     512, 568, 614, 664, 718, 754, 808, 871, 911, 985, 1033, 1115, 1171, 1231, 1286, 1354, 1426, 1502, 1582, 1666},
    {9, 16, 26, 36, 46, 60, 66, 86, 100, 122, 140, 158, 180, 197, 223, 253, 283, 313, 341, 385,
     406, 442, 464, 514, 538, 596, 628, 661, 701, 745, 793, 845, 901, 961, 986, 1054, 1096, 1142, 1222, 1276}}};
constexpr std::array<std::array<char, 40>, 4> kBlocks{{
    {1, 1, 1, 1, 1, 2, 2, 2, 2, 4, 4, 4, 4, 4, 6, 6, 6, 6, 7, 8, 8, 9, 9, 10, 12, 12, 12, 13, 14, 15, 16, 17, 18, 19, 19, 20, 21, 22, 24, 25},
    {1, 1, 1, 2, 2, 4, 4, 4, 5, 5, 5, 8, 9, 9, 10, 10, 11, 13, 14, 16, 17, 17, 18, 20, 21, 23, 25, 26, 28, 29, 31, 33, 35, 37, 38, 40, 43, 45, 47, 49},
    {1, 1, 2, 2, 4, 4, 6, 6, 8, 8, 8, 10, 12, 16, 12, 17, 16, 18, 21, 20, 23, 23, 25, 27, 29, 34, 34, 35, 38, 40, 43, 45, 48, 51, 53, 56, 59, 62, 65, 68},
    {1, 1, 2, 4, 4, 4, 5, 6, 8, 8, 11, 11, 16, 16, 18, 16, 19, 21, 25, 25, 25, 34, 30, 32, 35, 37, 40, 42, 45, 48, 51, 54, 57, 60, 63, 66, 70, 74, 77, 81}}};
constexpr std::array<short, 40> kTotalCodewords{
    26, 44, 70, 100, 134, 172, 196, 242, 292, 346, 404, 466, 532, 581, 655, 733, 815, 901, 991, 1085,
    1156, 1258, 1364, 1474, 1588, 1706, 1828, 1921, 2051, 2185, 2323, 2465, 2611, 2761, 2876, 3034, 3196, 3362, 3532, 3706};

int level_index(char ecc) {
  const std::size_t i = std::string_view("LMQH").find(ecc);
  if (i == std::string_view::npos) throw InputError(std::string("QR: error-correction level '") + ecc + "' is not one of L, M, Q, H");
  return static_cast<int>(i);
}

// Misdecode protection (Table 9's p): version 1 L 3, M 2, Q and H 1; version 2 L 2; 3 L 1.
int protection(int version, int level) {
  if (version == 1) return level == 0 ? 3 : level == 1 ? 2 : 1;
  if (version == 2 && level == 0) return 2;
  if (version == 3 && level == 0) return 1;
  return 0;
}

// Centres of the alignment patterns along either axis (Annex E's table, by its rule).
std::vector<int> alignment_centres(int version) {
  if (version == 1) return {};
  const int n = version / 7 + 2;
  const int step = version == 32 ? 26 : (version * 4 + n * 2 + 1) / (n * 2 - 2) * 2;
  std::vector<int> out{6};
  for (int i = 0, pos = version * 4 + 10; i < n - 1; ++i, pos -= step) out.insert(out.begin() + 1, pos);
  return out;
}

// The 15-bit format word (before the 0x5412 mask) for 5 data bits: BCH(15, 5).
int format_word(int data) {
  int rem = data;
  for (int i = 0; i < 10; ++i) rem = (rem << 1) ^ ((rem >> 9) * 0x537);
  return (data << 10 | rem) ^ 0x5412;
}

}  // namespace

SymbolMap qr_map(int version, char ecc) {
  if (version < 1 || version > 40) throw InputError("QR: version " + std::to_string(version) + " is outside 1 to 40");
  const int level = level_index(ecc);
  const int n = 17 + 4 * version;
  SymbolMap m;
  m.rows = m.cols = n;
  std::vector<char> function(static_cast<std::size_t>(n) * n, 0);
  const auto mark = [&](int r, int c) { function[static_cast<std::size_t>(r) * n + c] = 1; };

  // Finders with their separators: the 8 × 8 corner squares, segments A1 (top left), A2 (top
  // right), A3 (bottom left).
  const std::array<std::pair<int, int>, 3> corners{{{0, 0}, {0, n - 8}, {n - 8, 0}}};
  for (std::size_t k = 0; k < 3; ++k) {
    PatternSegment s{"A", {}, true};
    s.name.push_back(static_cast<char>('1' + k));
    for (int r = 0; r < 8; ++r)
      for (int c = 0; c < 8; ++c) {
        mark(corners[k].first + r, corners[k].second + c);
        s.modules.push_back({corners[k].first + r, corners[k].second + c});
      }
    m.segments.push_back(std::move(s));
  }
  // Timing patterns between the separators: B1 along row 6, B2 down column 6.
  PatternSegment b1{"B1", {}, false}, b2{"B2", {}, false};
  for (int i = 8; i < n - 8; ++i) {
    mark(6, i), b1.modules.push_back({6, i});
    mark(i, 6), b2.modules.push_back({i, 6});
  }
  m.segments.push_back(b1);
  m.segments.push_back(b2);
  // Alignment patterns, except where they would overlap a finder.
  PatternSegment align{"C", {}, false};
  const std::vector<int> centres = alignment_centres(version);
  for (std::size_t i = 0; i < centres.size(); ++i)
    for (std::size_t j = 0; j < centres.size(); ++j) {
      const bool on_finder = (i == 0 && j == 0) || (i == 0 && j + 1 == centres.size()) || (i + 1 == centres.size() && j == 0);
      if (on_finder) continue;
      for (int dr = -2; dr <= 2; ++dr)
        for (int dc = -2; dc <= 2; ++dc) {
          mark(centres[i] + dr, centres[j] + dc);
          align.modules.push_back({centres[i] + dr, centres[j] + dc});
        }
    }
  if (!align.modules.empty()) m.segments.push_back(align);
  // Format information (both copies) and the dark module; version information from version 7.
  for (int i = 0; i < 9; ++i) mark(8, i), mark(i, 8);
  for (int i = 0; i < 8; ++i) mark(8, n - 1 - i), mark(n - 1 - i, 8);
  if (version >= 7)
    for (int i = 0; i < 18; ++i) mark(n - 11 + i % 3, i / 3), mark(i / 3, n - 11 + i % 3);

  // Blocks: the short ones first, the long ones one data codeword longer.
  const int total = kTotalCodewords[static_cast<std::size_t>(version - 1)];
  const int data = kDataCodewords[static_cast<std::size_t>(level)][static_cast<std::size_t>(version - 1)];
  const int blocks = kBlocks[static_cast<std::size_t>(level)][static_cast<std::size_t>(version - 1)];
  const int ec = (total - data) / blocks;
  const int long_blocks = data % blocks, short_len = data / blocks;
  for (int b = 0; b < blocks; ++b)
    m.blocks.push_back({short_len + (b >= blocks - long_blocks ? 1 : 0), ec, protection(version, level)});
  // The stream: data codeword i of every block in turn, then error-correction codeword i.
  for (int i = 0; i <= short_len; ++i)
    for (int b = 0; b < blocks; ++b)
      if (i < m.blocks[static_cast<std::size_t>(b)].data) m.block_of.push_back(b);
  for (int i = 0; i < ec; ++i)
    for (int b = 0; b < blocks; ++b) m.block_of.push_back(b);

  // The zig-zag: column pairs from the right (the vertical timing column skipped), upward and
  // downward in turn, right module before left, function modules skipped; the bits of the
  // stream most significant first. Remainder modules carry no codeword.
  m.codeword.assign(static_cast<std::size_t>(n) * n, -1);
  m.bit.assign(m.codeword.size(), 0);
  int k = 0;
  const int bits = 8 * total;
  for (int right = n - 1; right >= 1; right -= 2) {
    if (right == 6) right = 5;
    const bool upward = ((right + 1) & 2) == 0;
    for (int v = 0; v < n; ++v)
      for (int j = 0; j < 2; ++j) {
        const int c = right - j, r = upward ? n - 1 - v : v;
        const std::size_t at = static_cast<std::size_t>(r) * n + c;
        if (function[at] || k >= bits) continue;
        m.codeword[at] = k / 8;
        m.bit[at] = 7 - k % 8;
        ++k;
      }
  }
  return m;
}

void qr_format(const ModuleMatrix& matrix, char& ecc, int& mask) {
  const int n = matrix.rows;
  if (matrix.symbology != Symbology::qr || n < 21 || matrix.cols != n)
    throw InputError("QR format information: not a QR symbol");
  // Bits 0–7 down column 8 (row 6, the timing pattern, skipped), 8–14 along row 8 leftward.
  int word = 0;
  for (int i = 0; i <= 5; ++i) word |= matrix.dark(i, 8) << i;
  word |= matrix.dark(7, 8) << 6;
  word |= matrix.dark(8, 8) << 7;
  word |= matrix.dark(8, 7) << 8;
  for (int i = 9; i < 15; ++i) word |= matrix.dark(8, 14 - i) << i;
  int best = -1, best_distance = 99;
  for (int data = 0; data < 32; ++data) {
    const int d = std::popcount(static_cast<unsigned>(format_word(data) ^ word));
    if (d < best_distance) best_distance = d, best = data;
  }
  if (best_distance > 3) throw InputError("QR format information does not decode");
  // Level bits: 01 L, 00 M, 11 Q, 10 H.
  ecc = "MLHQ"[best >> 3];
  mask = best & 7;
}

SymbolMap symbol_map(const ModuleMatrix& matrix) {
  switch (matrix.symbology) {
    case Symbology::datamatrix:
    case Symbology::gs1_datamatrix: return datamatrix_map(matrix.rows, matrix.cols);
    case Symbology::qr: {
      char ecc = 'M';
      int mask = 0;
      qr_format(matrix, ecc, mask);
      return qr_map((matrix.rows - 17) / 4, ecc);
    }
    default: throw InputError("a linear code has no module map");
  }
}

}  // namespace mark

#pragma once
// What each module of a 2-D symbol is for, as a verifier needs it: the codeword (and bit) a data
// module carries, the Reed–Solomon block of each codeword with its error-correction budget, and
// the fixed patterns (finders, clock and timing tracks, alignment patterns, the quiet zone
// beside the finder) graded for damage. Data Matrix after ISO/IEC 16022 (its Annex F placement;
// the size table is libdmtx's), QR after ISO/IEC 18004 (function patterns, the two-column
// zig-zag, block interleaving; the block table as zint and the standard's Table 9 give it).
#include <string>
#include <vector>

#include "marker/codes/module_matrix.hpp"

namespace mark {

struct RsBlock {
  int data = 0;        // data codewords
  int ec = 0;          // error-correction codewords
  int protection = 0;  // of those, reserved for misdecode protection (QR versions 1–3: Table 9)
};

struct PatternSegment {
  std::string name;  // "L1", "L2", "QZL1", "QZL2", "clock", "alignment" / "A1" … "B2", "C"
  // Modules (row, col) of the symbol; the quiet zone's lie outside 0..rows−1 × 0..cols−1.
  std::vector<std::pair<int, int>> modules;
  // Graded by the count of damaged modules (QR finders: 0, 1, 2, 3, more) rather than their share.
  bool by_count = false;
};

struct SymbolMap {
  int rows = 0, cols = 0;
  // Per module of the symbol (row-major): the codeword it carries a bit of (−1: none) and which
  // bit (7 the most significant).
  std::vector<int> codeword;
  std::vector<int> bit;
  std::vector<int> block_of;  // per codeword of the stream (data first, then error correction)
  std::vector<RsBlock> blocks;
  std::vector<PatternSegment> segments;

  int codeword_at(int row, int col) const { return codeword[static_cast<std::size_t>(row) * cols + col]; }
  int codewords() const { return static_cast<int>(block_of.size()); }
};

// ECC 200 of the given size (ISO/IEC 16022 square or rectangular). Throws InputError for a size
// that is not one.
SymbolMap datamatrix_map(int rows, int cols);

// QR of the given version (1–40) and error-correction level (L, M, Q, H). Throws InputError
// otherwise.
SymbolMap qr_map(int version, char ecc);

// The map of an encoded symbol: Data Matrix by its size, QR by its size and the error-correction
// level its format information carries (the level zint chose, which may be above the one asked
// for). Throws InputError for a linear code or a QR whose format information does not decode.
SymbolMap symbol_map(const ModuleMatrix& matrix);

// QR format information of an encoded symbol: error-correction level (L, M, Q, H) and mask
// (0–7), from the copy beside the top-left finder, to the nearest valid BCH word (up to 3 bits
// wrong). Throws InputError when it is farther than that.
void qr_format(const ModuleMatrix& matrix, char& ecc, int& mask);

}  // namespace mark

// Data Matrix ECC 200: where each codeword's eight modules are (ISO/IEC 16022 Annex F, the
// "utah" placement with its four corner cases, in the mapping matrix of the data regions), the
// interleaved Reed–Solomon blocks, and the fixed patterns. The size table is libdmtx's.
//
// Interleaving: codeword k of the whole stream (data, then error correction) belongs to block
// k mod B. Where the data divides evenly among the blocks this is the same as counting the
// error-correction codewords from block 0; only the 144 × 144 symbol (1558 data codewords in 10
// blocks) tells the two apart, and its symbols as zint 2.11 encodes them are valid Reed–Solomon
// blocks only this way (tests/marker/codes/symbol_map_test.cpp) — the arrangement ZXing reads and
// libdmtx 0.7.7, which counts from block 0, does not.
#include <dmtx.h>

#include "base/error.hpp"
#include "marker/codes/symbol_map.hpp"

namespace mark {
namespace {

// Annex F: each cell of the mapping matrix gets 10 × codeword + bit (codewords from 1, bits 1–8
// from the most significant); 1 marks the fixed corner modules, 0 an unvisited cell.
class Placement {
 public:
  Placement(int nrow, int ncol) : nrow_(nrow), ncol_(ncol), cells_(static_cast<std::size_t>(nrow) * ncol, 0) { place(); }
  int at(int row, int col) const { return cells_[static_cast<std::size_t>(row) * ncol_ + col]; }

 private:
  void module(int row, int col, int chr, int bit) {
    if (row < 0) row += nrow_, col += 4 - ((nrow_ + 4) % 8);
    if (col < 0) col += ncol_, row += 4 - ((ncol_ + 4) % 8);
    cells_[static_cast<std::size_t>(row) * ncol_ + col] = 10 * chr + bit;
  }
  void utah(int row, int col, int chr) {
    module(row - 2, col - 2, chr, 1);
    module(row - 2, col - 1, chr, 2);
    module(row - 1, col - 2, chr, 3);
    module(row - 1, col - 1, chr, 4);
    module(row - 1, col, chr, 5);
    module(row, col - 2, chr, 6);
    module(row, col - 1, chr, 7);
    module(row, col, chr, 8);
  }
  // The corner cases, each a list of (row, col) for bits 1–8; negative counts from the end.
  void corner(int chr, const int (&at)[8][2]) {
    for (int b = 0; b < 8; ++b) {
      const int r = at[b][0] < 0 ? nrow_ + at[b][0] : at[b][0];
      const int c = at[b][1] < 0 ? ncol_ + at[b][1] : at[b][1];
      module(r, c, chr, b + 1);
    }
  }
  bool free(int row, int col) const { return cells_[static_cast<std::size_t>(row) * ncol_ + col] == 0; }
  void place() {
    static const int corner1[8][2] = {{-1, 0}, {-1, 1}, {-1, 2}, {0, -2}, {0, -1}, {1, -1}, {2, -1}, {3, -1}};
    static const int corner2[8][2] = {{-3, 0}, {-2, 0}, {-1, 0}, {0, -4}, {0, -3}, {0, -2}, {0, -1}, {1, -1}};
    static const int corner3[8][2] = {{-3, 0}, {-2, 0}, {-1, 0}, {0, -2}, {0, -1}, {1, -1}, {2, -1}, {3, -1}};
    static const int corner4[8][2] = {{-1, 0}, {-1, -1}, {0, -3}, {0, -2}, {0, -1}, {1, -3}, {1, -2}, {1, -1}};
    int chr = 1, row = 4, col = 0;
    do {
      if (row == nrow_ && col == 0) corner(chr++, corner1);
      if (row == nrow_ - 2 && col == 0 && ncol_ % 4) corner(chr++, corner2);
      if (row == nrow_ - 2 && col == 0 && ncol_ % 8 == 4) corner(chr++, corner3);
      if (row == nrow_ + 4 && col == 2 && !(ncol_ % 8)) corner(chr++, corner4);
      do {  // up and to the right
        if (row < nrow_ && col >= 0 && free(row, col)) utah(row, col, chr++);
        row -= 2, col += 2;
      } while (row >= 0 && col < ncol_);
      row += 1, col += 3;
      do {  // down and to the left
        if (row >= 0 && col < ncol_ && free(row, col)) utah(row, col, chr++);
        row += 2, col -= 2;
      } while (row < nrow_ && col >= 0);
      row += 3, col += 1;
    } while (row < nrow_ || col < ncol_);
    if (free(nrow_ - 1, ncol_ - 1)) cells_[static_cast<std::size_t>(nrow_) * ncol_ - 1] =
        cells_[static_cast<std::size_t>(nrow_) * ncol_ - ncol_ - 2] = 1;
  }

  int nrow_, ncol_;
  std::vector<int> cells_;
};

int size_index(int rows, int cols) {
  for (int i = 0; i < DmtxSymbolSquareCount + DmtxSymbolRectCount; ++i)
    if (dmtxGetSymbolAttribute(DmtxSymAttribSymbolRows, i) == rows &&
        dmtxGetSymbolAttribute(DmtxSymAttribSymbolCols, i) == cols)
      return i;
  throw InputError("Data Matrix: " + std::to_string(rows) + "x" + std::to_string(cols) + " is not an ECC 200 size");
}

}  // namespace

SymbolMap datamatrix_map(int rows, int cols) {
  const int size = size_index(rows, cols);
  const auto attr = [size](int a) { return dmtxGetSymbolAttribute(a, size); };
  const int rr = attr(DmtxSymAttribDataRegionRows), rc = attr(DmtxSymAttribDataRegionCols);
  const int vr = attr(DmtxSymAttribVertDataRegions), hr = attr(DmtxSymAttribHorizDataRegions);
  SymbolMap m;
  m.rows = rows;
  m.cols = cols;
  m.codeword.assign(static_cast<std::size_t>(rows) * cols, -1);
  m.bit.assign(m.codeword.size(), 0);
  const Placement placement(vr * rr, hr * rc);
  for (int i = 0; i < vr * rr; ++i)
    for (int j = 0; j < hr * rc; ++j) {
      const int v = placement.at(i, j);
      if (v < 10) continue;  // the fixed corner
      const int r = (i / rr) * (rr + 2) + 1 + i % rr, c = (j / rc) * (rc + 2) + 1 + j % rc;
      m.codeword[static_cast<std::size_t>(r) * cols + c] = v / 10 - 1;
      m.bit[static_cast<std::size_t>(r) * cols + c] = 8 - v % 10;
    }
  // Blocks: codeword k of the stream belongs to block k mod B.
  const int blocks = attr(DmtxSymAttribInterleavedBlocks), data = attr(DmtxSymAttribSymbolDataWords);
  const int ec = attr(DmtxSymAttribSymbolErrorWords);
  m.blocks.assign(static_cast<std::size_t>(blocks), RsBlock{0, attr(DmtxSymAttribBlockErrorWords), 0});
  for (int k = 0; k < data + ec; ++k) {
    m.block_of.push_back(k % blocks);
    if (k < data) ++m.blocks[static_cast<std::size_t>(k % blocks)].data;
  }

  // Fixed patterns: the L (left column, bottom row) and the quiet zone beside it, the clock
  // tracks (top row, right column), and the borders of the inner data regions.
  PatternSegment l1{"L1", {}, false}, l2{"L2", {}, false}, qz1{"QZL1", {}, false}, qz2{"QZL2", {}, false};
  PatternSegment clock{"clock", {}, false}, align{"alignment", {}, false};
  for (int r = 0; r < rows; ++r) l1.modules.push_back({r, 0}), qz1.modules.push_back({r, -1});
  for (int c = 0; c < cols; ++c) l2.modules.push_back({rows - 1, c}), qz2.modules.push_back({rows, c});
  for (int c = 1; c < cols; ++c) clock.modules.push_back({0, c});
  for (int r = 1; r < rows - 1; ++r) clock.modules.push_back({r, cols - 1});
  for (int r = 1; r < rows - 1; ++r)
    for (int c = 1; c < cols - 1; ++c) {
      const bool border_row = (r % (rr + 2)) == 0 || (r % (rr + 2)) == rr + 1;
      const bool border_col = (c % (rc + 2)) == 0 || (c % (rc + 2)) == rc + 1;
      if (border_row || border_col) align.modules.push_back({r, c});
    }
  m.segments = {l1, l2, qz1, qz2, clock};
  if (!align.modules.empty()) m.segments.push_back(align);
  return m;
}

}  // namespace mark

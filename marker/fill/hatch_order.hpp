#pragma once
// The order in which hatch lines are drawn. Pieces on neighbouring scanlines that overlap one
// to one form a block (a cell of the boustrophedon decomposition): inside a block the beam steps
// one spacing to the next line, drawing serpentine (alternate directions) or one-way. The blocks
// are then visited in the shared visiting order (marker/order: nearest neighbour, 2-opt,
// relocation), each entered at whichever end keeps the jump short.
#include <vector>

#include "marker/fill/hatch_lines.hpp"

namespace mark {

struct HatchLine {
  Point start{0, 0};  // field frame, mm
  Point end{0, 0};
};

// Lines in drawing order. `at` is where the beam is before the first line; it is left at the
// end of the last. `raster` keeps scanline order, every line drawn the same way (the naive
// hatch the benchmark compares against).
std::vector<HatchLine> order_hatch(const std::vector<HatchPiece>& pieces, const HatchFrame& frame,
                                   HatchDirection direction, HatchOrder order, Point& at);

// Jump length from `at` through the lines in the given order (the first line's start
// included), mm.
double hatch_jump_length_mm(const std::vector<HatchLine>& lines, const Point& at);

}  // namespace mark

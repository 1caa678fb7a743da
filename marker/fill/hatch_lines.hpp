#pragma once
// Scanline hatching of a polygon area: the area is turned so the hatch direction lies along x,
// and every scanline y = (k + ½)·spacing (measured from the hatch origin across the hatch
// direction) is cut by the polygon edges; pairing the sorted crossings gives the pieces of the
// line inside the area (the area is a Clipper union: simple polygons, so even-odd pairing is
// exact). An edge spans [min y, max y) — half-open, so a scanline through a vertex is counted
// once and a scanline along a horizontal edge gives no zero-width piece.
#include <polyclipping/clipper.hpp>

#include <cstdint>
#include <vector>

#include "fonts/box.hpp"
#include "marker/fill/fill_options.hpp"

namespace mark {

// One piece of a scanline, in the turned frame: y = (row + ½)·spacing, x from x0 to x1 > x0.
struct HatchPiece {
  std::int64_t row = 0;
  double x0 = 0;
  double x1 = 0;
};

// The turned frame of one hatch set: field → frame is a rotation by −angle about the origin.
struct HatchFrame {
  Point origin{0, 0};
  double angle_rad = 0;
  double spacing_mm = 0.035;

  Point to_field(double x, double y) const;
  Point to_frame(const Point& field) const;
  double row_y(std::int64_t row) const { return (static_cast<double>(row) + 0.5) * spacing_mm; }
};

// The pieces of every scanline in row order, each row's pieces left to right; pieces shorter
// than min_line_mm are dropped. Throws InputError when the area would need more than
// `max_rows` scanlines (an absurd spacing for the size).
std::vector<HatchPiece> hatch_pieces(const ClipperLib::Paths& area, const HatchFrame& frame,
                                     double min_line_mm, std::int64_t max_rows = 2'000'000);

}  // namespace mark

#pragma once
// The control point generator of US 6,007,230 (FIG. 3, 4, 4A, 5A–5B). A cell is given by four
// density values along the track (0 = white … 1 = full black, first value first in time) and a
// CT / LW flag; it becomes the points the stylus toolpath passes through. Positions are in cell
// units (0 = where the cell begins on the track, 1 = where the next begins), depths in µm below
// the cylinder surface (negative: above it).
//
// The rules, as the seed gives them (block numbers of FIG. 5A–5B):
//
// - total density D = mean of the four values (block 92). D < 1 %: a non-engraved cell; one
//   point holds the stylus `lift` above the surface at the cell's middle (blocks 94–96).
// - multiple frequency (block 98) when d1 > d2 + d3 and d4 > d2 + d3: two sub-cells, one per
//   pair (d1, d2) and (d3, d4) (blocks 106–124), with pair densities D_A = (d1+d2)/2 and
//   D_B = (d3+d4)/2:
//     A: entry at the cell start, depth = channel scaler of d1;
//        centre at the density centre of the pair, depth = full-cell scaler of D_A;
//        exit on the surface at D1 = D_A · D2 from the start (D2 = the pair's half of the cell);
//     B: entry on the surface at D3 = D_B · D2 before the cell end;
//        centre at the density centre of the pair, depth = full-cell scaler of D_B;
//        exit at the cell end, depth = channel scaler of d4.
// - otherwise one cell (blocks 100–104): centre at the centre of image density — the point with
//   as much density before it as after it, each value spread evenly over its quarter — at the
//   full-cell scaler of D. Entry and exit:
//     D > 90 %: at the cell boundaries, below the surface at the channel scaler of d1 and d4
//               (claims 11–12: the stylus stays in the copper and joins the next dark cell);
//     else:     on the surface, placed about the centre (claim 10) a distance D apart in cell
//               units (claim 8: the total density sets them, as D1 and D3 do for sub-cells),
//               moved as a whole to stay inside the cell.
//
// A centre is kept at least a quarter of its (sub-)cell's length from its entry and exit, so the
// spline through them stays a single dip; for a pair or cell whose density sits at its middle
// the density centre already is there (FIG. 4: a full-black value makes a sub-cell centred on it).
#include <array>
#include <cstdint>
#include <string_view>

#include "marker/gravure/cell_setup.hpp"

namespace mark {

struct CellValues {
  std::array<float, 4> density{};  // 0 .. 1, along the track
  bool line_work = false;          // LW (else CT) setup values
};

enum class CellKind : std::uint8_t {
  white,    // D < 1 %: stylus held above the surface
  single,   // one cell, entry and exit on the surface
  channel,  // D > 90 %: one cell, entry and exit below the surface
  split     // multiple frequency: two sub-cells
};
std::string_view to_string(CellKind kind);

struct ControlPoint {
  double x = 0;         // cell units, 0 .. 1
  double depth_um = 0;  // below the surface
};

struct CellPlan {
  CellKind kind = CellKind::white;
  std::uint8_t count = 0;               // points used
  std::array<ControlPoint, 6> points{};  // in ascending x
};

// Densities must be finite and within 0 .. 1 (the image reader guarantees it).
CellPlan plan_cell(const CellValues& cell, const GravureSetup& setup);

// The density centre of values spread evenly over [from, to) in equal parts: the position with
// half the density before it (the middle of the span where that is ambiguous).
double density_centre(const float* values, int count, double from, double to);

}  // namespace mark

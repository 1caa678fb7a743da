#pragma once
// How a closed shape is filled with laser lines: the fill rule that decides inside from
// outside, one or more hatch sets (each its own angle and spacing: two sets at 0° and 90° are a
// cross-hatch), serpentine or one-way lines, the inset of the hatch from the contour (a beam
// radius, so the mark ends on the outline rather than half a line width beyond it) and contour
// passes — loops that follow the outline, before or after the hatch. The parameters are the
// ones EzCad, LightBurn and SAMLight users set (fonts_cnc.md §5).
#include <string_view>
#include <vector>

#include "fonts/box.hpp"

namespace mark {

enum class FillRule { non_zero, even_odd };
enum class HatchDirection { bidirectional, unidirectional };
// raster: every line in scanline order, each drawn the same way (what a naive hatcher does;
// kept for comparison); short: serpentine blocks ordered to keep jumps short.
enum class HatchOrder { short_jumps, raster };
enum class ContourPlacement { before, after };

struct HatchSet {
  double angle_deg = 0;      // direction of the lines, from +x counter-clockwise
  // Distance between neighbouring lines: a little under the default 40 µm line, so the lines
  // of a hatch overlap into a solid fill.
  double spacing_mm = 0.035;
  // Apply the inset along the lines only (each line's ends pulled in by it) instead of shrinking
  // the area: for rectilinear shapes hatched along their own grid (a code's modules), whose
  // spacing divides the grid so every line already runs half a spacing off the edges beside it.
  bool inset_line_ends_only = false;
};

struct FillOptions {
  FillRule rule = FillRule::non_zero;  // TrueType and CFF outlines are non-zero
  std::vector<HatchSet> sets{HatchSet{}};
  HatchDirection direction = HatchDirection::bidirectional;
  HatchOrder order = HatchOrder::short_jumps;
  double inset_mm = 0.02;      // hatch lines end this far inside the contour (the default beam radius)
  // Scanlines lie at origin + (k + ½)·spacing across the hatch direction, in the field frame,
  // so neighbouring shapes filled apart still get collinear lines.
  Point origin{0, 0};
  int contour_passes = 0;      // loops along the outline (0: hatch only)
  ContourPlacement contour_placement = ContourPlacement::before;
  double contour_inset_mm = 0.02;     // the first loop's distance inside the outline
  double contour_spacing_mm = 0.035;  // between loops
  // Hatch pieces shorter than this are dropped: where a scanline grazes a curve it leaves a piece
  // of a few µm whose burn is the beam's spot alone, and which the locus, one tick of 10 µs
  // (10 µm at 1 m/s) at least, would overdose many times over.
  double min_line_mm = 0.01;
  // Arcs are flattened within this for the booleans; contour passes are re-fitted to the exact
  // lines and arcs afterwards.
  double chord_tolerance_mm = 0.0005;
};

std::string_view to_string(FillRule rule);
std::string_view to_string(HatchDirection direction);
std::string_view to_string(HatchOrder order);
std::string_view to_string(ContourPlacement placement);
// Names as the command line spells them; each throws InputError naming the value otherwise.
FillRule parse_fill_rule(std::string_view name);            // nonzero, evenodd
HatchDirection parse_hatch_direction(std::string_view name);  // bidirectional, unidirectional
HatchOrder parse_hatch_order(std::string_view name);        // short, raster
ContourPlacement parse_contour_placement(std::string_view name);  // before, after

// Throws InputError naming the first parameter outside its range (and the range).
void check_fill_options(const FillOptions& options);

}  // namespace mark

#pragma once
// The fill stage: closed contours → lit elements that cover their area — contour passes and
// hatch lines in drawing order, laser-off moves between them. The output is ordinary elements,
// so the planner's blanking, delays and everything downstream treat hatch lines like any other
// stroke.
#include <cstddef>
#include <vector>

#include "marker/fill/contours.hpp"
#include "marker/fill/fill_options.hpp"
#include "marker/layout/figure.hpp"

namespace mark {

struct FillStats {
  std::size_t hatch_lines = 0;
  double hatch_length_mm = 0;
  std::size_t contour_loops = 0;
  double contour_length_mm = 0;
  double jump_length_mm = 0;  // laser-off moves from the start point through every piece
  double area_mm2 = 0;        // of the unioned contours

  FillStats& operator+=(const FillStats& o);
};

struct Filled {
  std::vector<Element> elements;  // lit pieces, laser-off lines between them
  FillStats stats;
};

// Throws InputError for options outside their ranges. `at` is where the beam is before the
// fill; it is left where the fill ends.
Filled fill_contours(const std::vector<Contour>& contours, const FillOptions& options, Point& at);

// Every glyph of the figure filled on its own (the glyph order, and so the marking order, is
// kept; hatch lines of neighbouring glyphs are collinear because the scanlines are fixed in the
// field frame). Throws InputError naming the glyph if one is not closed (a single-line font).
Figure fill_figure(const Figure& figure, const FillOptions& options, FillStats* stats = nullptr);

}  // namespace mark

#pragma once
// The area a fill covers: closed contours flattened (within a chord tolerance) and unioned by
// Clipper under the fill rule, so overlapping contours — TrueType glyphs often overlap their
// own parts, a code's modules touch their neighbours — become one area without seams or
// doubled strips. The exact source elements are kept beside the polygons: the contour passes
// re-fit their loops to them (lines stay lines, arcs become arcs again).
#include <polyclipping/clipper.hpp>

#include <vector>

#include "marker/fill/contours.hpp"
#include "marker/fill/fill_options.hpp"

namespace mark {

struct FillRegion {
  ClipperLib::Paths area;        // simple polygons in nanometres, holes oriented opposite
  std::vector<Element> sources;  // every element of the contours, field mm
  double chord_tolerance_mm = 0;

  bool empty() const { return area.empty(); }
  double area_mm2() const;
  // The area shrunk by inset_mm (round joins), as polygons.
  ClipperLib::Paths inset(double inset_mm) const;
};

FillRegion make_fill_region(const std::vector<Contour>& contours, FillRule rule,
                            double chord_tolerance_mm);

}  // namespace mark

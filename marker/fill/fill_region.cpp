#include "marker/fill/fill_region.hpp"

#include "marker/geometry/clipper_paths.hpp"
#include "marker/geometry/flatten.hpp"

namespace mark {

using namespace ClipperLib;

double FillRegion::area_mm2() const { return mark::area_mm2(area); }

Paths FillRegion::inset(double inset_mm) const {
  if (inset_mm <= 0) return area;
  // Round joins within the chord tolerance: the inset follows the outline as closely as the
  // outline itself was flattened.
  return offset_region(area, -inset_mm, chord_tolerance_mm);
}

FillRegion make_fill_region(const std::vector<Contour>& contours, FillRule rule,
                            double chord_tolerance_mm) {
  FillRegion region;
  region.chord_tolerance_mm = chord_tolerance_mm;
  Paths polygons;
  for (const Contour& c : contours) {
    Path p;
    for (const Element& e : c.elements) {
      region.sources.push_back(e);
      const std::vector<Point> pts = flatten_element(e, chord_tolerance_mm);
      for (std::size_t k = 0; k + 1 < pts.size(); ++k) {  // the next element starts on the end
        const IntPoint q = to_nm(pts[k]);
        if (p.empty() || p.back() != q) p.push_back(q);
      }
    }
    if (p.size() >= 3) polygons.push_back(std::move(p));
  }
  const PolyFillType type = rule == FillRule::non_zero ? pftNonZero : pftEvenOdd;
  Clipper c;
  c.AddPaths(polygons, ptSubject, true);
  c.Execute(ctUnion, region.area, type, type);
  return region;
}

}  // namespace mark

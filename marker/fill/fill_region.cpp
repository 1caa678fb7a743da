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
    region.sources.insert(region.sources.end(), c.elements.begin(), c.elements.end());
    Path p = loop_polygon(c.elements, chord_tolerance_mm);
    if (p.size() >= 3) polygons.push_back(std::move(p));
  }
  region.area = union_polygons(polygons, rule == FillRule::even_odd);
  return region;
}

}  // namespace mark

#include "marker/job/auto_speed.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <variant>

#include "fonts/overloaded.hpp"

namespace mark {

double tightest_radius_mm(const Figure& figure) {
  double r = std::numeric_limits<double>::infinity();
  for (const PlacedGlyph& g : figure.glyphs)
    for (const Element& e : g.elements) {
      if (!e.laser()) continue;
      r = std::min(r, std::visit(Overloaded{[](const Line&) {
                                              return std::numeric_limits<double>::infinity();
                                            },
                                            [](const CircularArc& a) { return a.radius; },
                                            [](const EllipticalArc& a) {
                                              const double big = std::max(a.rx, a.ry);
                                              const double small = std::min(a.rx, a.ry);
                                              return big > 0 ? small * small / big : 0.0;
                                            }},
                                 e.geometry()));
    }
  return r;
}

double auto_mark_speed_mm_s(const Figure& figure, const HeadModel& head) {
  const double r = tightest_radius_mm(figure);
  if (!std::isfinite(r)) return kAutoSpeedCap_mm_s;
  return std::min(kAutoSpeedCap_mm_s, std::sqrt(2 * r * kAutoSpeedShrink_mm) / head.tau_s);
}

}  // namespace mark

#include "marker/fill/hatch_lines.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "base/error.hpp"
#include "marker/geometry/clipper_paths.hpp"

namespace mark {

Point HatchFrame::to_field(double x, double y) const {
  const double c = std::cos(angle_rad), s = std::sin(angle_rad);
  return origin + Point(c * x - s * y, s * x + c * y);
}

Point HatchFrame::to_frame(const Point& p) const {
  const double c = std::cos(angle_rad), s = std::sin(angle_rad);
  const Point d = p - origin;
  return Point(c * d.x() + s * d.y(), -s * d.x() + c * d.y());
}

std::vector<HatchPiece> hatch_pieces(const ClipperLib::Paths& area, const HatchFrame& frame,
                                     double min_line_mm, std::int64_t max_rows) {
  std::vector<HatchPiece> out;
  // The area's polygons in the turned frame, and the rows they span.
  std::vector<std::vector<Point>> polys;
  double y_min = INFINITY, y_max = -INFINITY;
  for (const ClipperLib::Path& path : area) {
    if (path.size() < 3) continue;
    std::vector<Point>& poly = polys.emplace_back();
    poly.reserve(path.size());
    for (const ClipperLib::IntPoint& q : path) {
      poly.push_back(frame.to_frame(to_mm(q)));
      y_min = std::min(y_min, poly.back().y());
      y_max = std::max(y_max, poly.back().y());
    }
  }
  if (polys.empty()) return out;
  const double d = frame.spacing_mm;
  // Row k's line is at (k + ½)·d: the first row at or above y_min, the last below y_max.
  const auto first = static_cast<std::int64_t>(std::ceil(y_min / d - 0.5));
  const auto last = static_cast<std::int64_t>(std::ceil(y_max / d - 0.5)) - 1;
  if (last < first) return out;
  if (last - first + 1 > max_rows)
    throw InputError("hatch spacing " + std::to_string(d) + " mm would need " +
                     std::to_string(last - first + 1) + " lines across " +
                     std::to_string(y_max - y_min) + " mm (at most " + std::to_string(max_rows) + ")");

  std::vector<std::vector<double>> crossings(static_cast<std::size_t>(last - first + 1));
  for (const std::vector<Point>& poly : polys) {
    for (std::size_t i = 0; i < poly.size(); ++i) {
      const Point& a = poly[i];
      const Point& b = poly[(i + 1) % poly.size()];
      if (a.y() == b.y()) continue;
      const Point& lo = a.y() < b.y() ? a : b;
      const Point& hi = a.y() < b.y() ? b : a;
      // Rows with lo.y ≤ (k + ½)d < hi.y.
      const auto k0 = std::max(first, static_cast<std::int64_t>(std::ceil(lo.y() / d - 0.5)));
      auto k1 = std::min(last, static_cast<std::int64_t>(std::ceil(hi.y() / d - 0.5)) - 1);
      for (std::int64_t k = k0; k <= k1; ++k) {
        const double y = frame.row_y(k);
        if (y < lo.y() || y >= hi.y()) continue;  // rounding at the ends of the range
        const double t = (y - lo.y()) / (hi.y() - lo.y());
        crossings[static_cast<std::size_t>(k - first)].push_back(lo.x() + t * (hi.x() - lo.x()));
      }
    }
  }
  for (std::size_t r = 0; r < crossings.size(); ++r) {
    std::vector<double>& xs = crossings[r];
    std::sort(xs.begin(), xs.end());
    for (std::size_t i = 0; i + 1 < xs.size(); i += 2)
      if (xs[i + 1] - xs[i] >= min_line_mm)
        out.push_back({first + static_cast<std::int64_t>(r), xs[i], xs[i + 1]});
  }
  return out;
}

}  // namespace mark

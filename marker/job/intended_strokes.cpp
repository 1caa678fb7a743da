#include "marker/job/intended_strokes.hpp"

#include <algorithm>
#include <cmath>

#include "fonts/overloaded.hpp"
#include "marker/plan/stroke.hpp"

namespace mark {
namespace {

// Points per element so that parameter-uniform points are ≤ step apart: the parameter speed of
// an arc or ellipse never exceeds its largest radius × |sweep|.
std::size_t pieces(const Element& e, double step_mm) {
  const double reach = std::visit(
      Overloaded{[](const Line& l) { return (l.end - l.start).norm(); },
                 [](const CircularArc& a) { return a.radius * std::abs(a.sweep); },
                 [](const EllipticalArc& a) { return std::max(a.rx, a.ry) * std::abs(a.sweep); }},
      e.geometry());
  return std::max<std::size_t>(1, static_cast<std::size_t>(std::ceil(reach / step_mm)));
}

}  // namespace

std::vector<std::vector<Vec2>> intended_polylines(const Figure& figure, double step_mm) {
  std::vector<std::vector<Vec2>> out;
  for (const Stroke& s : strokes_of(figure)) {
    std::vector<Vec2> line;
    const Point p0 = s.start();
    line.push_back({p0.x(), p0.y()});
    for (const Element& e : s.elements) {
      const std::size_t n = pieces(e, step_mm);
      for (std::size_t i = 1; i <= n; ++i) {
        const Point p = e.point_at(static_cast<double>(i) / n);
        line.push_back({p.x(), p.y()});
      }
    }
    if (s.closed()) line.back() = line.front();  // exactly, so the quality figures see it closed
    out.push_back(std::move(line));
  }
  return out;
}

}  // namespace mark

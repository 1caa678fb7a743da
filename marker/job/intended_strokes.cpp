#include "marker/job/intended_strokes.hpp"

#include "marker/geometry/flatten.hpp"
#include "marker/plan/stroke.hpp"

namespace mark {

std::vector<std::vector<Vec2>> intended_polylines(const Figure& figure, double step_mm) {
  std::vector<std::vector<Vec2>> out;
  for (const Stroke& s : strokes_of(figure)) {
    std::vector<Vec2> line;
    const Point p0 = s.start();
    line.push_back({p0.x(), p0.y()});
    for (const Element& e : s.elements)
      // A straight element is one segment: cutting it adds points, not accuracy (the quality
      // reference samples every segment at its own step).
      for_each_piece_end(e, std::holds_alternative<Line>(e.geometry()) ? 1 : spaced_count(e, std::max(step_mm, 0.005)),
                         [&](double x, double y) { line.push_back({x, y}); });
    if (s.closed()) line.back() = line.front();  // exactly, so the quality figures see it closed
    out.push_back(std::move(line));
  }
  return out;
}

}  // namespace mark

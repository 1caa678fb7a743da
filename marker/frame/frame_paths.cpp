#include "marker/frame/frame_paths.hpp"

#include <algorithm>
#include <string>

#include "base/error.hpp"
#include "marker/geometry/flatten.hpp"
#include "marker/plan/stroke.hpp"

namespace mark {
namespace {

std::vector<std::vector<Vec2>> flattened_strokes(const Figure& figure, double tol) {
  std::vector<std::vector<Vec2>> out;
  for (const Stroke& s : strokes_of(figure)) {
    std::vector<Vec2> line;
    for (const Element& e : s.elements) {
      const std::vector<Point> pts = flatten_element(e, tol);
      for (std::size_t i = line.empty() ? 0 : 1; i < pts.size(); ++i)
        line.push_back({pts[i].x(), pts[i].y()});
    }
    if (line.size() >= 2) out.push_back(std::move(line));
  }
  return out;
}

double cross(Vec2 o, Vec2 a, Vec2 b) { return (a.x - o.x) * (b.y - o.y) - (a.y - o.y) * (b.x - o.x); }

// Andrew's monotone chain; the result is closed (last point = first).
std::vector<Vec2> convex_hull(std::vector<Vec2> pts) {
  std::sort(pts.begin(), pts.end(), [](Vec2 a, Vec2 b) { return a.x < b.x || (a.x == b.x && a.y < b.y); });
  pts.erase(std::unique(pts.begin(), pts.end(), [](Vec2 a, Vec2 b) { return a.x == b.x && a.y == b.y; }),
            pts.end());
  if (pts.size() < 3) {
    if (!pts.empty()) pts.push_back(pts.front());
    return pts;
  }
  std::vector<Vec2> h(2 * pts.size());
  std::size_t k = 0;
  for (const Vec2& p : pts) {
    while (k >= 2 && cross(h[k - 2], h[k - 1], p) <= 0) --k;
    h[k++] = p;
  }
  for (std::size_t i = pts.size() - 1, t = k + 1; i-- > 0;) {
    while (k >= t && cross(h[k - 2], h[k - 1], pts[i]) <= 0) --k;
    h[k++] = pts[i];
  }
  h.resize(k);  // the chain ends on its first point: closed
  return h;
}

}  // namespace

FrameShape parse_frame_shape(std::string_view name) {
  if (name == "box") return FrameShape::box;
  if (name == "hull") return FrameShape::hull;
  if (name == "strokes") return FrameShape::strokes;
  throw InputError("--shape '" + std::string(name) + "' is not one of box, hull, strokes");
}

std::vector<std::vector<Vec2>> frame_paths(const Figure& figure, FrameShape shape,
                                           double chord_tolerance_mm) {
  std::vector<std::vector<Vec2>> strokes = flattened_strokes(figure, chord_tolerance_mm);
  if (strokes.empty()) throw InputError("frame: the job marks nothing, there is nothing to frame");
  if (shape == FrameShape::strokes) return strokes;
  if (shape == FrameShape::hull) {
    std::vector<Vec2> all;
    for (const auto& s : strokes) all.insert(all.end(), s.begin(), s.end());
    return {convex_hull(std::move(all))};
  }
  const Box b = figure.bounds();
  return {{{b.min.x(), b.min.y()}, {b.max.x(), b.min.y()}, {b.max.x(), b.max.y()},
           {b.min.x(), b.max.y()}, {b.min.x(), b.min.y()}}};
}

}  // namespace mark

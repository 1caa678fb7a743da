#include "marker/cnc/cut_moves.hpp"

#include "fonts/overloaded.hpp"

namespace mark {

void append_cut(const std::vector<Element>& path, double z, double feed, std::vector<ToolMove>& out) {
  for (const Element& e : path) {
    const Point end = e.end();
    std::visit(Overloaded{[&](const CircularArc& a) {
                            out.push_back(ToolMove::arc(end.x(), end.y(), z, a.center, a.sweep > 0, feed));
                          },
                          [&](const auto&) { out.push_back(ToolMove::feed(end.x(), end.y(), z, feed)); }},
               e.geometry());
  }
}

std::vector<Element> machinable(const std::vector<Element>& elements, const ArcSplineOptions& arcs) {
  std::vector<Element> out;
  for (const Element& e : elements) {
    std::vector<Element> pieces = arc_spline(e, arcs);
    out.insert(out.end(), pieces.begin(), pieces.end());
  }
  return out;
}

}  // namespace mark

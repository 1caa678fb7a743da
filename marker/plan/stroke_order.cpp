// Jump-length minimisation: an open path through the strokes (start at home, no return), each
// stroke entered at either end. The visiting order is the one shared with the CNC export
// (marker/order): nearest neighbour with reversal, then 2-opt and relocation.
#include "marker/plan/stroke_order.hpp"

#include <string>

#include "base/error.hpp"
#include "marker/order/visit_order.hpp"

namespace mark {
namespace {

double dist(const Point& a, const Point& b) { return (a - b).norm(); }

}  // namespace
std::string_view to_string(StrokeOrder order) {
  return order == StrokeOrder::glyph ? "glyph" : "shortest";
}

StrokeOrder parse_stroke_order(std::string_view name) {
  if (name == "glyph") return StrokeOrder::glyph;
  if (name == "shortest") return StrokeOrder::shortest;
  throw InputError("stroke order '" + std::string(name) + "' is not one of glyph, shortest");
}

double jump_length_mm(const std::vector<Stroke>& strokes, const Point& home) {
  double len = 0;
  Point at = home;
  for (const Stroke& s : strokes) {
    len += dist(at, s.start());
    at = s.end();
  }
  return len;
}

std::vector<Stroke> order_strokes(std::vector<Stroke> strokes, StrokeOrder order,
                                  const Point& home) {
  if (order == StrokeOrder::glyph || strokes.size() < 2) return strokes;
  std::vector<VisitItem> items;
  items.reserve(strokes.size());
  for (const Stroke& s : strokes) items.push_back(VisitItem::stroke(s.start(), s.end()));
  std::vector<Stroke> tour;
  tour.reserve(strokes.size());
  for (const VisitStep& step : plan_visit_order(items, home))
    tour.push_back(step.reversed ? strokes[step.item].reversed() : std::move(strokes[step.item]));
  return tour;
}

}  // namespace mark

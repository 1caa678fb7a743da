#include "marker/cnc/depression.hpp"

#include <map>

#include "base/error.hpp"
#include "fonts/stroke_font.hpp"
#include "marker/cnc/cut_moves.hpp"
#include "marker/cnc/cut_strokes.hpp"
#include "marker/order/visit_order.hpp"

namespace mark {
namespace {

// One subprogram body: every stroke, all passes, strokes in the order that keeps rapids short.
// An open stroke cut in several passes goes back and forth (odd passes forward, even passes
// backward) so no pass starts with a rapid; a closed stroke goes round the same way each pass.
ToolSubprogram letter_subprogram(const ShapedGlyph& shape, const CutSettings& s,
                                 const std::vector<double>& depths, Point& entry, Point& exit) {
  std::vector<CutStroke> strokes = chain_cut_strokes(shape.elements);
  std::vector<std::vector<Element>> paths;
  std::vector<VisitItem> items;
  const bool even = depths.size() % 2 == 0;
  for (const CutStroke& st : strokes) {
    paths.push_back(machinable(st.elements, s.arcs));
    const Point a = st.start(), b = st.end();
    if (st.closed() || !even)
      items.push_back(VisitItem::stroke(a, st.closed() ? a : b));
    else
      items.push_back({a, a, true, b, b});  // even passes come back to where they started
  }
  const std::vector<VisitStep> order = plan_visit_order(items, Point(0, 0));

  ToolSubprogram sub;
  sub.label = describe_code_point(shape.code_point);
  for (std::size_t k = 0; k < order.size(); ++k) {
    const VisitStep& step = order[k];
    const std::vector<Element>& fwd = paths[step.item];
    std::vector<Element> bwd;
    for (auto it = fwd.rbegin(); it != fwd.rend(); ++it) bwd.push_back(it->reversed());
    const std::vector<Element>& first = step.reversed ? bwd : fwd;
    const std::vector<Element>& second = step.reversed ? fwd : bwd;
    const bool closed = strokes[step.item].closed();
    const Point p0 = first.front().start();
    if (k == 0) entry = p0;
    sub.body.push_back(ToolMove::rapid(p0.x(), p0.y(), s.safe_z_mm));
    Point at = p0;
    for (std::size_t pass = 0; pass < depths.size(); ++pass) {
      const std::vector<Element>& path = (closed || pass % 2 == 0) ? first : second;
      sub.body.push_back(ToolMove::feed(at.x(), at.y(), depths[pass], s.plunge_feed_mm_min));
      append_cut(path, depths[pass], s.feed_mm_min, sub.body);
      at = path.back().end();
    }
    sub.body.push_back(ToolMove::rapid(at.x(), at.y(), s.safe_z_mm));
    exit = at;
  }
  return sub;
}

}  // namespace

Toolpath depression_toolpath(const Figure& figure, const CutSettings& s) {
  validate(s);
  const std::vector<double> depths = pass_depths(s);
  Toolpath tp;
  tp.safe_z_mm = s.safe_z_mm;

  // Subprograms for the shapes that are used and have something to cut.
  std::map<std::size_t, std::size_t> sub_of_shape;
  std::vector<Point> entries, exits;
  for (const PlacedGlyph& g : figure.glyphs) {
    if (sub_of_shape.count(g.shape)) continue;
    const ShapedGlyph& shape = figure.shapes.at(g.shape);
    bool lit = false;
    for (const Element& e : shape.elements) lit = lit || e.laser();
    if (!lit) continue;
    Point entry(0, 0), exit(0, 0);
    tp.subs.push_back(letter_subprogram(shape, s, depths, entry, exit));
    entries.push_back(entry);
    exits.push_back(exit);
    sub_of_shape[g.shape] = tp.subs.size() - 1;
  }

  // Occurrences in an order that keeps the rapids between letters short.
  std::vector<SubprogramCall> calls;
  std::vector<VisitItem> items;
  for (const PlacedGlyph& g : figure.glyphs) {
    auto it = sub_of_shape.find(g.shape);
    if (it == sub_of_shape.end()) continue;
    const Affine place = g.placement();
    calls.push_back({it->second, g.origin, g.rotation_rad});
    items.push_back(VisitItem::fixed(place * entries[it->second], place * exits[it->second]));
  }
  if (calls.empty()) throw InputError("depression: the text has no strokes to engrave");
  for (const VisitStep& step : plan_visit_order(items, items.front().entry)) tp.steps.push_back(calls[step.item]);
  return tp;
}

}  // namespace mark

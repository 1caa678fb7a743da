#include "marker/cnc/depression.hpp"

#include <map>
#include <tuple>

#include "base/error.hpp"
#include "fonts/stroke_font.hpp"
#include "fonts/stroke_join.hpp"
#include "marker/cnc/cut_moves.hpp"
#include "marker/order/visit_order.hpp"

namespace mark {
namespace {

// One stroke of a distinct character, ready to cut: its machinable path both ways.
struct LetterStroke {
  std::vector<Element> forward, backward;  // lines and arcs (arc-splined)
  bool closed = false;
};

std::vector<LetterStroke> letter_strokes(const ShapedGlyph& shape, double join_tol, const ArcSplineOptions& arcs) {
  std::vector<LetterStroke> out;
  for (const ChainedStroke& st : chain_strokes(shape.elements, join_tol)) {
    LetterStroke ls;
    ls.forward = machinable(st.elements, arcs);
    for (auto it = ls.forward.rbegin(); it != ls.forward.rend(); ++it) ls.backward.push_back(it->reversed());
    ls.closed = st.closed(join_tol);
    out.push_back(std::move(ls));
  }
  return out;
}

// The visiting item of one stroke: an open stroke cut in an even number of passes goes there and
// back and leaves where it entered; a closed one goes round and has no useful reverse.
VisitItem stroke_item(const LetterStroke& st, const Affine& place, bool even_passes) {
  const Point a = place * st.forward.front().start(), b = place * st.forward.back().end();
  if (st.closed) return VisitItem::fixed(a, a);
  if (even_passes) return {a, a, true, b, b};
  return VisitItem::stroke(a, b);
}

// One stroke, all passes: open strokes go back and forth (odd passes forward, even passes
// backward) so no pass starts with a rapid; closed ones go round the same way each pass.
ToolSubprogram stroke_subprogram(const LetterStroke& st, bool reversed, const CutSettings& s,
                                 const std::vector<double>& depths, std::string label) {
  ToolSubprogram sub;
  sub.label = std::move(label);
  const std::vector<Element>& first = reversed ? st.backward : st.forward;
  const std::vector<Element>& second = reversed ? st.forward : st.backward;
  const Point p0 = first.front().start();
  sub.body.push_back(ToolMove::rapid(p0.x(), p0.y(), s.safe_z_mm));
  Point at = p0;
  for (std::size_t pass = 0; pass < depths.size(); ++pass) {
    const std::vector<Element>& path = (st.closed || pass % 2 == 0) ? first : second;
    sub.body.push_back(ToolMove::feed(at.x(), at.y(), depths[pass], s.plunge_feed_mm_min));
    append_cut(path, depths[pass], s.feed_mm_min, sub.body);
    at = path.back().end();
  }
  sub.body.push_back(ToolMove::rapid(at.x(), at.y(), s.safe_z_mm));
  return sub;
}

}  // namespace

Toolpath depression_toolpath(const Figure& figure, const CutSettings& s, const Progress& progress) {
  validate(s);
  const std::vector<double> depths = pass_depths(s);
  const bool even = depths.size() % 2 == 0;
  const double join_tol = figure.join_tolerance_mm();

  // The strokes of each distinct character that is used.
  std::map<std::size_t, std::vector<LetterStroke>> strokes_of_shape;
  for (const PlacedGlyph& g : figure.glyphs)
    if (!strokes_of_shape.count(g.shape))
      strokes_of_shape[g.shape] = letter_strokes(figure.shapes.at(g.shape), join_tol, s.arcs);

  // Every stroke of every occurrence, ordered together.
  struct Occurrence {
    std::size_t glyph, stroke;
  };
  std::vector<Occurrence> occurrences;
  std::vector<VisitItem> items;
  for (std::size_t g = 0; g < figure.glyphs.size(); ++g) {
    if (g % 256 == 0) progress.step("gcode: collecting strokes", g, figure.glyphs.size());
    const PlacedGlyph& pg = figure.glyphs[g];
    const std::vector<LetterStroke>& strokes = strokes_of_shape[pg.shape];
    const Affine place = pg.placement();
    for (std::size_t k = 0; k < strokes.size(); ++k) {
      occurrences.push_back({g, k});
      items.push_back(stroke_item(strokes[k], place, even));
    }
  }
  if (items.empty()) throw InputError("depression: the text has no strokes to engrave");

  Toolpath tp;
  tp.safe_z_mm = s.safe_z_mm;
  // A subprogram per (character, stroke, direction) that is cut.
  std::map<std::tuple<std::size_t, std::size_t, bool>, std::size_t> sub_of;
  const std::vector<VisitStep> order = plan_visit_order(items, items.front().entry, progress);
  for (std::size_t k = 0; k < order.size(); ++k) {
    if (k % 256 == 0) progress.step("gcode: building toolpaths", k, order.size());
    const Occurrence& o = occurrences[order[k].item];
    const PlacedGlyph& pg = figure.glyphs[o.glyph];
    const std::vector<LetterStroke>& strokes = strokes_of_shape[pg.shape];
    const bool reversed = order[k].reversed && !strokes[o.stroke].closed;
    const auto key = std::make_tuple(pg.shape, o.stroke, reversed);
    auto it = sub_of.find(key);
    if (it == sub_of.end()) {
      std::string label = describe_code_point(pg.code_point) + " stroke " + std::to_string(o.stroke + 1) +
                          " of " + std::to_string(strokes.size()) + (reversed ? " reversed" : "");
      tp.subs.push_back(stroke_subprogram(strokes[o.stroke], reversed, s, depths, std::move(label)));
      it = sub_of.emplace(key, tp.subs.size() - 1).first;
    }
    tp.steps.push_back(SubprogramCall{it->second, pg.origin, pg.rotation_rad});
  }
  return tp;
}

}  // namespace mark

#include "marker/fill/fill.hpp"

#include <cmath>
#include <numbers>

#include "fonts/stroke_font.hpp"
#include "marker/fill/contour_passes.hpp"
#include "marker/fill/fill_region.hpp"
#include "marker/fill/hatch_order.hpp"

namespace mark {
namespace {

// Appends a lit piece, with a laser-off move from wherever the last piece ended.
void append_piece(std::vector<Element>& out, const std::vector<Element>& piece, Point& at,
                  FillStats& stats) {
  if (piece.empty()) return;
  const double jump = (piece.front().start() - at).norm();
  stats.jump_length_mm += jump;
  if (!out.empty() && jump > 0) out.push_back(Element::line(at, piece.front().start(), false));
  out.insert(out.end(), piece.begin(), piece.end());
  at = piece.back().end();
}

void append_contours(const FillRegion& region, const FillOptions& o, std::vector<Element>& out,
                     Point& at, FillStats& stats) {
  Point beam = at;
  for (const std::vector<Element>& loop : contour_loops(region, o, beam)) {
    ++stats.contour_loops;
    for (const Element& e : loop) stats.contour_length_mm += e.length();
    append_piece(out, loop, at, stats);
  }
}

}  // namespace

FillStats& FillStats::operator+=(const FillStats& o) {
  hatch_lines += o.hatch_lines;
  hatch_length_mm += o.hatch_length_mm;
  contour_loops += o.contour_loops;
  contour_length_mm += o.contour_length_mm;
  jump_length_mm += o.jump_length_mm;
  area_mm2 += o.area_mm2;
  return *this;
}

Filled fill_contours(const std::vector<Contour>& contours, const FillOptions& o, Point& at) {
  check_fill_options(o);
  Filled result;
  const FillRegion region = make_fill_region(contours, o.rule, o.chord_tolerance_mm);
  result.stats.area_mm2 = region.area_mm2();
  if (region.empty()) return result;
  if (o.contour_passes > 0 && o.contour_placement == ContourPlacement::before)
    append_contours(region, o, result.elements, at, result.stats);
  const ClipperLib::Paths hatch_area = region.inset(o.inset_mm);
  for (const HatchSet& set : o.sets) {
    const HatchFrame frame{o.origin, set.angle_deg * std::numbers::pi / 180, set.spacing_mm};
    std::vector<HatchPiece> pieces;
    if (set.inset_line_ends_only) {
      for (HatchPiece p : hatch_pieces(region.area, frame, 0.0)) {
        p.x0 += o.inset_mm;
        p.x1 -= o.inset_mm;
        if (p.x1 - p.x0 >= o.min_line_mm) pieces.push_back(p);
      }
    } else {
      pieces = hatch_pieces(hatch_area, frame, o.min_line_mm);
    }
    Point beam = at;
    const std::vector<HatchLine> lines = order_hatch(pieces, frame, o.direction, o.order, beam);
    for (const HatchLine& l : lines) {
      ++result.stats.hatch_lines;
      result.stats.hatch_length_mm += (l.end - l.start).norm();
      append_piece(result.elements, {Element::line(l.start, l.end)}, at, result.stats);
    }
  }
  if (o.contour_passes > 0 && o.contour_placement == ContourPlacement::after)
    append_contours(region, o, result.elements, at, result.stats);
  return result;
}

Figure fill_figure(const Figure& figure, const FillOptions& options, FillStats* stats) {
  check_fill_options(options);
  Figure out = figure;
  Point at(0, 0);
  FillStats total;
  for (PlacedGlyph& g : out.glyphs) {
    const std::vector<Contour> contours =
        closed_contours(g.elements, "glyph " + describe_code_point(g.code_point));
    Filled f = fill_contours(contours, options, at);
    total += f.stats;
    g.elements = std::move(f.elements);
  }
  if (stats) *stats = total;
  return out;
}

}  // namespace mark

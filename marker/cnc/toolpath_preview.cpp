#include "marker/cnc/toolpath_preview.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "marker/geometry/clipper_paths.hpp"
#include "marker/preview/canvas.hpp"

namespace mark {
namespace {

constexpr double kWidthPx = 1200;

constexpr Rgb kStock{0.93, 0.86, 0.62}, kCleared{0.80, 0.89, 0.98}, kLetters{0.93, 0.78, 0.35},
    kUncut{0.9, 0.05, 0.05}, kToolCentre{0.05, 0.15, 0.55}, kRapid{0.85, 0.2, 0.1};

// Grey for a carve at `fraction` of the deepest: light near the surface, dark at the bottom.
Rgb depth_shade(double fraction) {
  const double v = 0.85 - 0.75 * std::clamp(fraction, 0.0, 1.0);
  return {v, v, v};
}

std::vector<LegendEntry> legend(const ProtrusionResult* prot, const VCarveResult* vcarve, double deepest_mm) {
  std::vector<LegendEntry> l;
  if (vcarve) {
    l.push_back({"v-carve, shallow", depth_shade(0.1), LegendMark::area});
    char deep[64];
    std::snprintf(deep, sizeof deep, "v-carve, %.3f mm deep", deepest_mm);
    l.push_back({deep, depth_shade(1), LegendMark::area});
    if (vcarve->flat_area_mm2 > 0) l.push_back({"flat bottom (end mill)", kCleared, LegendMark::area});
  } else if (prot) {
    l.push_back({"stock plate", kStock, LegendMark::area});
    l.push_back({"cleared pocket", kCleared, LegendMark::area});
    l.push_back({"raised letters", kLetters, LegendMark::area});
    if (!prot->uncut.empty()) l.push_back({"material the tool cannot reach", kUncut, LegendMark::area});
  } else {
    l.push_back({"groove at full depth (one tool wide)", kCleared, LegendMark::area});
  }
  l.push_back({"tool centre, cutting", kToolCentre, LegendMark::line});
  l.push_back({"rapid moves", kRapid, LegendMark::dashed});
  return l;
}

void add_paths(cairo_t* cr, const ClipperLib::Paths& paths) {
  for (const ClipperLib::Path& p : paths) {
    if (p.empty()) continue;
    const Point a = to_mm(p.front());
    cairo_move_to(cr, a.x(), a.y());
    for (const ClipperLib::IntPoint& q : p) {
      const Point b = to_mm(q);
      cairo_line_to(cr, b.x(), b.y());
    }
    cairo_close_path(cr);
  }
}

void fill_paths(cairo_t* cr, const ClipperLib::Paths& paths, const Rgb& c) {
  cairo_set_fill_rule(cr, CAIRO_FILL_RULE_EVEN_ODD);
  add_paths(cr, paths);
  cairo_set_source_rgb(cr, c.r, c.g, c.b);
  cairo_fill(cr);
}

// The XY path of one move from `from`.
void add_move(cairo_t* cr, const Point& from, const ToolMove& m) {
  cairo_move_to(cr, from.x(), from.y());
  const Point to(m.end.x(), m.end.y());
  if (m.kind != MoveKind::arc) {
    cairo_line_to(cr, to.x(), to.y());
    return;
  }
  const double r = (from - m.center).norm();
  const double a0 = std::atan2(from.y() - m.center.y(), from.x() - m.center.x());
  const double a1 = std::atan2(to.y() - m.center.y(), to.x() - m.center.x());
  if (m.ccw)
    cairo_arc(cr, m.center.x(), m.center.y(), r, a0, a1);
  else
    cairo_arc_negative(cr, m.center.x(), m.center.y(), r, a0, a1);
}

}  // namespace

// A V-carve: every cutting move as the band the cone cuts at the surface (its radius there is
// depth · tan(half angle), changing linearly along the move), shallow ones first so the deeper
// ones lie on top.
void draw_carve(cairo_t* cr, const std::vector<ToolMove>& moves, double tan_half, double deepest) {
  struct Piece {
    Point a, b;
    double ra, rb, depth;
  };
  std::vector<Piece> pieces;
  for (std::size_t k = 1; k < moves.size(); ++k) {
    const ToolMove& m = moves[k];
    const ToolMove& prev = moves[k - 1];
    if (m.kind != MoveKind::feed || m.end.z() >= 0 || prev.end.z() > 0) continue;
    const double za = -prev.end.z(), zb = -m.end.z();
    pieces.push_back({prev.end.head<2>(), m.end.head<2>(), za * tan_half, zb * tan_half, std::max(za, zb)});
  }
  std::sort(pieces.begin(), pieces.end(), [](const Piece& x, const Piece& y) { return x.depth < y.depth; });
  for (const Piece& p : pieces) {
    const Rgb c = depth_shade(deepest > 0 ? p.depth / deepest : 0);
    cairo_set_source_rgb(cr, c.r, c.g, c.b);
    cairo_new_path(cr);
    cairo_arc(cr, p.a.x(), p.a.y(), p.ra, 0, 2 * M_PI);
    cairo_fill(cr);
    cairo_arc(cr, p.b.x(), p.b.y(), p.rb, 0, 2 * M_PI);
    cairo_fill(cr);
    const Point d = p.b - p.a;
    if (d.norm() <= 0) continue;
    const Point n = Point(-d.y(), d.x()) / d.norm();
    cairo_move_to(cr, p.a.x() + n.x() * p.ra, p.a.y() + n.y() * p.ra);
    cairo_line_to(cr, p.b.x() + n.x() * p.rb, p.b.y() + n.y() * p.rb);
    cairo_line_to(cr, p.b.x() - n.x() * p.rb, p.b.y() - n.y() * p.rb);
    cairo_line_to(cr, p.a.x() - n.x() * p.ra, p.a.y() - n.y() * p.ra);
    cairo_close_path(cr);
    cairo_fill(cr);
  }
}

void write_toolpath_preview(const Figure& figure, const Toolpath& toolpath, double tool_diameter_mm,
                            const ProtrusionResult* prot, const std::string& path, const VCarveResult* vcarve) {
  const std::vector<ToolMove> moves = expand_moves(toolpath);
  Box view = figure.bounds();
  if (prot) view.add(prot->plate);
  for (const ToolMove& m : moves) view.add(Point(m.end.x(), m.end.y()));
  const double pad = std::max(0.05 * std::max(view.width(), view.height()), tool_diameter_mm);
  view.min -= Point(pad, pad);
  view.max += Point(pad, pad);
  double deepest = 0;
  for (const ToolMove& m : moves) deepest = std::min(deepest, m.end.z());
  Canvas canvas(path, view, kWidthPx / std::max(view.width(), 1e-3), legend(prot, vcarve, -deepest));
  cairo_t* cr = canvas.cr();
  if (vcarve) {
    draw_carve(cr, moves, std::tan(vcarve->half_angle_rad), -deepest);
    // Flat bottoms of every occurrence, on top of the carve that surrounds them.
    for (const ToolStep& st : toolpath.steps)
      if (const auto* call = std::get_if<SubprogramCall>(&st)) {
        ClipperLib::Paths placed = vcarve->letters[call->sub].flat;
        const Affine place = Eigen::Translation2d(call->origin) * Eigen::Rotation2Dd(call->rotation_rad);
        for (ClipperLib::Path& ring : placed)
          for (ClipperLib::IntPoint& q : ring) q = to_nm(place * to_mm(q));
        fill_paths(cr, placed, kCleared);
      }
  }

  if (prot) {
    cairo_rectangle(cr, prot->plate.min.x(), prot->plate.min.y(), prot->plate.width(), prot->plate.height());
    cairo_set_source_rgb(cr, kStock.r, kStock.g, kStock.b);
    cairo_fill(cr);
    fill_paths(cr, prot->cleared, kCleared);
    fill_paths(cr, prot->letters, kLetters);
    fill_paths(cr, prot->uncut_region, kUncut);
  }

  // Depression: the groove the tool cuts at full depth, one tool wide.
  Point at(0, 0);
  bool known = false;
  if (!prot && !vcarve) {
    for (const ToolMove& m : moves) {
      if (known && m.kind != MoveKind::rapid && m.end.z() <= deepest + 1e-9) add_move(cr, at, m);
      at = Point(m.end.x(), m.end.y());
      known = true;
    }
    cairo_set_source_rgb(cr, kCleared.r, kCleared.g, kCleared.b);
    cairo_set_line_width(cr, tool_diameter_mm);
    cairo_stroke(cr);
  }
  // Tool-centre path: cuts solid, rapids dashed.
  known = false;
  for (const ToolMove& m : moves) {
    if (known && m.kind != MoveKind::rapid) add_move(cr, at, m);
    at = Point(m.end.x(), m.end.y());
    known = true;
  }
  cairo_set_source_rgb(cr, kToolCentre.r, kToolCentre.g, kToolCentre.b);
  canvas.set_line_px(1.0);
  cairo_stroke(cr);
  known = false;
  for (const ToolMove& m : moves) {
    if (known && m.kind == MoveKind::rapid && (Point(m.end.x(), m.end.y()) - at).norm() > 1e-9) {
      cairo_move_to(cr, at.x(), at.y());
      cairo_line_to(cr, m.end.x(), m.end.y());
    }
    at = Point(m.end.x(), m.end.y());
    known = true;
  }
  cairo_set_source_rgba(cr, kRapid.r, kRapid.g, kRapid.b, 0.7);
  canvas.set_line_px(0.8);
  canvas.set_dash_px(4, 3);
  cairo_stroke(cr);
  canvas.set_dash_px(0, 0);
  canvas.finish();
}

}  // namespace mark

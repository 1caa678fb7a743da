#include "marker/peen/peen_preview.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "marker/preview/canvas.hpp"

namespace mark {
namespace {

constexpr Rgb kWindow{0.55, 0.55, 0.55}, kRoute{0.85, 0.25, 0.1}, kDot{0.05, 0.15, 0.55}, kHome{0.1, 0.55, 0.2};

std::vector<LegendEntry> legend(const PeenPlan& plan) {
  std::vector<LegendEntry> l{{"dots struck", kDot, LegendMark::dot}, {"needle route", kRoute, LegendMark::line}};
  for (const PlanStop& s : plan.stops)
    if (!s.dot) {
      l.push_back({"turns without a strike", kRoute, LegendMark::area});
      break;
    }
  l.push_back({"marking window", kWindow, LegendMark::line});
  l.push_back({"home", kHome, LegendMark::dot});
  return l;
}

}  // namespace

void write_peen_preview(const DotText& text, const PeenPlan& plan, const Box& window,
                        const std::string& path) {
  Box view = window;
  view.add(text.bounds());
  view.add(plan.home_mm);
  const double margin = std::max({view.width(), view.height(), 1.0}) * 0.03;
  view.add(view.min - Point(margin, margin));
  view.add(view.max + Point(margin, margin));
  const double px_per_mm = std::clamp(1200.0 / view.width(), 2.0, 400.0);
  Canvas canvas(path, view, px_per_mm, legend(plan));
  cairo_t* cr = canvas.cr();

  cairo_rectangle(cr, window.min.x(), window.min.y(), window.width(), window.height());
  cairo_set_source_rgb(cr, kWindow.r, kWindow.g, kWindow.b);
  canvas.set_line_px(1.0);
  cairo_stroke(cr);

  // The route: home, every stop, home.
  cairo_move_to(cr, plan.home_mm.x(), plan.home_mm.y());
  for (const PlanStop& s : plan.stops) cairo_line_to(cr, s.pos_mm.x(), s.pos_mm.y());
  cairo_line_to(cr, plan.home_mm.x(), plan.home_mm.y());
  cairo_set_source_rgba(cr, kRoute.r, kRoute.g, kRoute.b, 0.75);
  canvas.set_line_px(1.0);
  cairo_stroke(cr);

  const double r = std::max(text.pitch_mm * 0.3, 0.5 / px_per_mm);
  for (const Dot& d : text.dots) {
    cairo_new_sub_path(cr);
    cairo_arc(cr, d.pos_mm.x(), d.pos_mm.y(), r, 0, 2 * std::numbers::pi);
  }
  cairo_set_source_rgb(cr, kDot.r, kDot.g, kDot.b);
  cairo_fill(cr);

  const double sq = r * 0.8;
  for (const PlanStop& s : plan.stops)
    if (!s.dot) cairo_rectangle(cr, s.pos_mm.x() - sq / 2, s.pos_mm.y() - sq / 2, sq, sq);
  cairo_set_source_rgb(cr, kRoute.r, kRoute.g, kRoute.b);
  cairo_fill(cr);

  cairo_new_sub_path(cr);
  cairo_arc(cr, plan.home_mm.x(), plan.home_mm.y(), 2 * r, 0, 2 * std::numbers::pi);
  cairo_set_source_rgb(cr, kHome.r, kHome.g, kHome.b);
  canvas.set_line_px(2.0);
  cairo_stroke(cr);
  canvas.finish();
}

}  // namespace mark

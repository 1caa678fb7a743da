#include "marker/preview/figure_preview.hpp"

#include <algorithm>
#include <cmath>

#include "marker/preview/cairo_path.hpp"
#include "marker/preview/canvas.hpp"

namespace mark {
namespace {

constexpr double kOverviewPx = 520;  // the whole field, left panel
constexpr double kDetailPx = 1100;   // the figure enlarged, right panel
constexpr double kGapPx = 16;

constexpr Rgb kMarkColour{0.05, 0.15, 0.55}, kTravelColour{0.85, 0.2, 0.1}, kFieldColour{0.2, 0.2, 0.2},
    kDetailColour{0.1, 0.6, 0.2}, kGuideColour{0.55, 0.55, 0.55};

std::vector<LegendEntry> legend(const PreviewOptions& o, bool two_panels) {
  std::vector<LegendEntry> l{{"marks (laser on)", kMarkColour, LegendMark::line}};
  if (o.show_travel) l.push_back({"travel between strokes (laser off)", kTravelColour, LegendMark::dashed});
  l.push_back({"field frame and centre", kFieldColour, LegendMark::line});
  if (o.circle) l.push_back({"circular-fitting circle and centre", kGuideColour, LegendMark::dashed});
  if (two_panels) l.push_back({"enlarged on the right", kDetailColour, LegendMark::line});
  return l;
}

void set_colour(cairo_t* cr, const Rgb& c, double alpha = 1) { cairo_set_source_rgba(cr, c.r, c.g, c.b, alpha); }


// The pen's route through the figure: travel from each stroke's end to the next stroke's start,
// whether the glyph data holds that move as a laser-off element or it falls between glyphs.
// Paths are stroked every few hundred glyphs: one cairo_stroke of a whole long text cannot be
// stopped, a run of short ones can.
constexpr std::size_t kGlyphsPerStroke = 256;

void draw_travel(Canvas& canvas, const Figure& figure, const Progress& progress) {
  cairo_t* cr = canvas.cr();
  bool have_pen = false;
  Point pen;
  set_colour(cr, kTravelColour, 0.8);
  canvas.set_line_px(1.0);
  canvas.set_dash_px(4, 3);
  for (std::size_t k = 0; k < figure.glyphs.size(); ++k) {
    if (k % kGlyphsPerStroke == 0) {
      cairo_stroke(cr);
      progress.step("preview: drawing the travel of glyph", k, figure.glyphs.size());
    }
    for (const Element& e : figure.glyphs[k].elements) {
      if (!e.laser()) continue;
      if (have_pen && (e.start() - pen).norm() > 1e-9) {
        cairo_move_to(cr, pen.x(), pen.y());
        cairo_line_to(cr, e.start().x(), e.start().y());
      }
      pen = e.end();
      have_pen = true;
    }
  }
  cairo_stroke(cr);
  canvas.set_dash_px(0, 0);
}

// The circle the letters of a circular fitting stand on (their baseline), and its centre.
void draw_circle_guide(Canvas& canvas, const CircleFit& c) {
  cairo_t* cr = canvas.cr();
  cairo_new_sub_path(cr);
  cairo_arc(cr, c.center.x(), c.center.y(), c.radius_mm, 0, 2 * M_PI);
  const double tick = std::min(c.radius_mm * 0.1, 8.0 / canvas.px_per_mm());
  cairo_move_to(cr, c.center.x() - tick, c.center.y());
  cairo_line_to(cr, c.center.x() + tick, c.center.y());
  cairo_move_to(cr, c.center.x(), c.center.y() - tick);
  cairo_line_to(cr, c.center.x(), c.center.y() + tick);
  set_colour(cr, kGuideColour);
  canvas.set_line_px(1.0);
  canvas.set_dash_px(6, 4);
  cairo_stroke(cr);
  canvas.set_dash_px(0, 0);
}

void draw_field(Canvas& canvas, const Field& field) {
  cairo_t* cr = canvas.cr();
  const Box f = field.box();
  cairo_rectangle(cr, f.min.x(), f.min.y(), f.width(), f.height());
  set_colour(cr, kFieldColour);
  canvas.set_line_px(1.5);
  cairo_stroke(cr);
  const double tick = field.size_mm * 0.02;
  cairo_move_to(cr, -tick, 0);
  cairo_line_to(cr, tick, 0);
  cairo_move_to(cr, 0, -tick);
  cairo_line_to(cr, 0, tick);
  set_colour(cr, kFieldColour, 0.5);
  canvas.set_line_px(1.0);
  cairo_stroke(cr);
}

void draw_marks(Canvas& canvas, const Figure& figure, const Progress& progress) {
  cairo_t* cr = canvas.cr();
  set_colour(cr, kMarkColour);
  canvas.set_line_px(std::clamp(canvas.px_per_mm() * 0.08, 1.2, 3.0));
  for (std::size_t k = 0; k < figure.glyphs.size(); ++k) {
    if (k % kGlyphsPerStroke == 0) {
      cairo_stroke(cr);
      progress.step("preview: drawing glyph", k, figure.glyphs.size());
    }
    for (const Element& e : figure.glyphs[k].elements)
      if (e.laser()) append_element(cr, e);
  }
  cairo_stroke(cr);
}

void draw_panel(Canvas& canvas, const Figure& figure, const Field& field, const PreviewOptions& o) {
  draw_field(canvas, field);
  if (o.circle) draw_circle_guide(canvas, *o.circle);
  if (o.show_travel) draw_travel(canvas, figure, *o.progress);
  draw_marks(canvas, figure, *o.progress);
}

}  // namespace

void write_figure_preview(const Figure& figure, const Field& field, const std::string& path,
                          const PreviewOptions& options) {
  const Box overview = field.box().grown(field.size_mm * 0.02);
  const Box bounds = figure.bounds();
  const bool small = !bounds.empty() && std::max(bounds.width(), bounds.height()) < 0.4 * field.size_mm;
  if (options.px_per_mm > 0 || !small) {
    // One panel: the whole field.
    const double scale = options.px_per_mm > 0 ? options.px_per_mm : 1200.0 / overview.width();
    Canvas canvas(path, overview, scale, legend(options, false));
    draw_panel(canvas, figure, field, options);
    canvas.finish();
    return;
  }
  // A small figure gets two panels: the whole field, and the figure enlarged beside it.
  const Box detail = bounds.grown(std::max(0.5, 0.08 * std::max(bounds.width(), bounds.height())));
  const double detail_scale = std::min(kDetailPx / detail.width(), kDetailPx / detail.height());
  const double detail_h = detail.height() * detail_scale;
  const double overview_scale = kOverviewPx / overview.width();
  const int width = static_cast<int>(std::ceil(kOverviewPx + kGapPx + detail.width() * detail_scale));
  const int height = static_cast<int>(std::ceil(std::max(kOverviewPx, detail_h)));
  Canvas canvas(path, width, height, legend(options, true));
  canvas.set_view(overview, 0, (height - kOverviewPx) / 2, overview_scale);
  draw_panel(canvas, figure, field, options);
  // Where the enlarged panel looks.
  cairo_rectangle(canvas.cr(), detail.min.x(), detail.min.y(), detail.width(), detail.height());
  set_colour(canvas.cr(), kDetailColour);
  canvas.set_line_px(1.0);
  cairo_stroke(canvas.cr());
  canvas.set_view(detail, kOverviewPx + kGapPx, (height - detail_h) / 2, detail_scale);
  cairo_rectangle(canvas.cr(), detail.min.x(), detail.min.y(), detail.width(), detail.height());
  set_colour(canvas.cr(), kDetailColour);
  canvas.set_line_px(2.0);
  cairo_stroke(canvas.cr());
  draw_panel(canvas, figure, field, options);
  canvas.finish();
}

}  // namespace mark

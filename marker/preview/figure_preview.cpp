#include "marker/preview/figure_preview.hpp"

#include <algorithm>

#include "marker/preview/cairo_path.hpp"
#include "marker/preview/canvas.hpp"

namespace mark {
namespace {

// The pen's route through the figure: travel from each stroke's end to the next stroke's start,
// whether the glyph data holds that move as a laser-off element or it falls between glyphs.
void draw_travel(Canvas& canvas, const Figure& figure) {
  cairo_t* cr = canvas.cr();
  bool have_pen = false;
  Point pen;
  for (const PlacedGlyph& g : figure.glyphs) {
    for (const Element& e : g.elements) {
      if (!e.laser()) continue;
      if (have_pen && (e.start() - pen).norm() > 1e-9) {
        cairo_move_to(cr, pen.x(), pen.y());
        cairo_line_to(cr, e.start().x(), e.start().y());
      }
      pen = e.end();
      have_pen = true;
    }
  }
  cairo_set_source_rgba(cr, 0.85, 0.2, 0.1, 0.8);
  canvas.set_line_px(1.0);
  canvas.set_dash_px(4, 3);
  cairo_stroke(cr);
  canvas.set_dash_px(0, 0);
}

}  // namespace

void write_figure_preview(const Figure& figure, const Field& field, const std::string& path,
                          const PreviewOptions& options) {
  Box view = field.box();
  const double margin = field.size_mm * 0.02;
  view.add(view.min - Point(margin, margin));
  view.add(view.max + Point(margin, margin));
  const double px_per_mm = options.px_per_mm > 0 ? options.px_per_mm : 1200.0 / view.width();
  Canvas canvas(path, view, px_per_mm);
  cairo_t* cr = canvas.cr();

  // Field frame and its centre cross.
  const Box f = field.box();
  cairo_rectangle(cr, f.min.x(), f.min.y(), f.width(), f.height());
  cairo_set_source_rgb(cr, 0.2, 0.2, 0.2);
  canvas.set_line_px(1.5);
  cairo_stroke(cr);
  const double tick = field.size_mm * 0.02;
  cairo_move_to(cr, -tick, 0);
  cairo_line_to(cr, tick, 0);
  cairo_move_to(cr, 0, -tick);
  cairo_line_to(cr, 0, tick);
  cairo_set_source_rgb(cr, 0.6, 0.6, 0.6);
  canvas.set_line_px(1.0);
  cairo_stroke(cr);

  if (options.show_travel) draw_travel(canvas, figure);

  for (const PlacedGlyph& g : figure.glyphs)
    for (const Element& e : g.elements)
      if (e.laser()) append_element(cr, e);
  cairo_set_source_rgb(cr, 0.05, 0.15, 0.55);
  canvas.set_line_px(std::clamp(px_per_mm * 0.08, 1.2, 3.0));
  cairo_stroke(cr);
  canvas.finish();
}

}  // namespace mark

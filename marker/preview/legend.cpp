#include "marker/preview/legend.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace mark {
namespace {

constexpr double kPad = 10;         // px around the strip's contents
constexpr double kScaleRowPx = 30;  // the scale bars' row
constexpr double kRowPx = 22;       // one row of legend entries
constexpr double kSwatchPx = 26;
constexpr double kFontPx = 12;
constexpr double kEntryGapPx = 18;

void font(cairo_t* cr) {
  cairo_select_font_face(cr, "sans-serif", CAIRO_FONT_SLANT_NORMAL, CAIRO_FONT_WEIGHT_NORMAL);
  cairo_set_font_size(cr, kFontPx);
}

double text_width(cairo_t* cr, const std::string& s) {
  cairo_text_extents_t e;
  cairo_text_extents(cr, s.c_str(), &e);
  return e.x_advance;
}

// An entry's width: swatch, gap, label. Measured on a scratch surface where no canvas exists yet.
double entry_width(cairo_t* cr, const LegendEntry& e) { return kSwatchPx + 6 + text_width(cr, e.label) + kEntryGapPx; }

// Rows the entries take when they flow left to right and wrap at the picture's width.
int rows(cairo_t* cr, const std::vector<LegendEntry>& entries, int width_px) {
  int n = entries.empty() ? 0 : 1;
  double x = kPad;
  for (const LegendEntry& e : entries) {
    const double w = entry_width(cr, e);
    if (x > kPad && x + w > width_px - kPad) ++n, x = kPad;
    x += w;
  }
  return n;
}

void swatch(cairo_t* cr, const LegendEntry& e, double x, double y_mid) {
  cairo_set_source_rgb(cr, e.colour.r, e.colour.g, e.colour.b);
  switch (e.mark) {
    case LegendMark::area:
      cairo_rectangle(cr, x, y_mid - 6, kSwatchPx, 12);
      cairo_fill(cr);
      break;
    case LegendMark::dot:
      cairo_arc(cr, x + kSwatchPx / 2, y_mid, 4, 0, 2 * M_PI);
      cairo_fill(cr);
      break;
    case LegendMark::line:
    case LegendMark::dashed: {
      const double dash[2] = {4, 3};
      cairo_set_dash(cr, dash, e.mark == LegendMark::dashed ? 2 : 0, 0);
      cairo_set_line_width(cr, 2);
      cairo_move_to(cr, x, y_mid);
      cairo_line_to(cr, x + kSwatchPx, y_mid);
      cairo_stroke(cr);
      cairo_set_dash(cr, nullptr, 0, 0);
      break;
    }
  }
}

void scale_bar(cairo_t* cr, const PanelScale& p, double top_px) {
  const double mm = scale_bar_mm(p.px_per_mm, std::max(20.0, p.width_px * 0.3));
  const double len = mm * p.px_per_mm, x0 = p.x_px + kPad, y = top_px + 12;
  cairo_set_source_rgb(cr, 0, 0, 0);
  cairo_set_line_width(cr, 2);
  cairo_move_to(cr, x0, y);
  cairo_line_to(cr, x0 + len, y);
  for (double x : {x0, x0 + len}) {
    cairo_move_to(cr, x, y - 5);
    cairo_line_to(cr, x, y + 5);
  }
  cairo_stroke(cr);
  char label[32];
  std::snprintf(label, sizeof label, "%g mm", mm);
  cairo_move_to(cr, x0 + len + 8, y + kFontPx / 2 - 2);
  cairo_show_text(cr, label);
}

}  // namespace

double scale_bar_mm(double px_per_mm, double max_px) {
  const double max_mm = max_px / px_per_mm;
  double step = std::pow(10.0, std::floor(std::log10(max_mm)));
  for (double f : {5.0, 2.0, 1.0})
    if (f * step <= max_mm) return f * step;
  return step;
}

int legend_height_px(const std::vector<LegendEntry>& entries, int width_px) {
  cairo_surface_t* scratch = cairo_image_surface_create(CAIRO_FORMAT_A8, 1, 1);
  cairo_t* cr = cairo_create(scratch);
  font(cr);
  const int n = rows(cr, entries, width_px);
  cairo_destroy(cr);
  cairo_surface_destroy(scratch);
  return static_cast<int>(std::ceil(kScaleRowPx + n * kRowPx + kPad));
}

void draw_legend(cairo_t* cr, const std::vector<PanelScale>& panels, const std::vector<LegendEntry>& entries,
                 double top_px, int width_px) {
  cairo_save(cr);
  cairo_identity_matrix(cr);
  cairo_reset_clip(cr);
  font(cr);
  cairo_move_to(cr, 0, top_px + 0.5);
  cairo_line_to(cr, width_px, top_px + 0.5);
  cairo_set_source_rgb(cr, 0.8, 0.8, 0.8);
  cairo_set_line_width(cr, 1);
  cairo_stroke(cr);
  for (const PanelScale& p : panels) scale_bar(cr, p, top_px + 6);
  double x = kPad, row_mid = top_px + kScaleRowPx + kRowPx / 2;
  for (const LegendEntry& e : entries) {
    const double w = entry_width(cr, e);
    if (x > kPad && x + w > width_px - kPad) x = kPad, row_mid += kRowPx;
    swatch(cr, e, x, row_mid);
    cairo_set_source_rgb(cr, 0.1, 0.1, 0.1);
    cairo_move_to(cr, x + kSwatchPx + 6, row_mid + kFontPx / 2 - 2);
    cairo_show_text(cr, e.label.c_str());
    x += w;
  }
  cairo_restore(cr);
}

}  // namespace mark

#include "marker/gravure/gravure_preview.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

#include "driver/sim/stylus_cells.hpp"
#include "marker/gravure/stylus_toolpath.hpp"
#include "marker/preview/canvas.hpp"

namespace mark {
namespace {

constexpr double kMaxPanelPx = 1000;
constexpr double kGapPx = 24, kTitlePx = 28;

// One panel: per track, the widest opening (and its depth) in every pixel column.
void draw_panel(Canvas& canvas, const GravureLayout& g, std::span<const float> cut, double px_per_mm,
                double deepest_um) {
  cairo_t* cr = canvas.cr();
  const double pitch_mm = g.cell_pitch_um / 1000, track_mm = g.track_pitch_um / 1000;
  const double half_width = std::tan(g.stylus_angle_deg * std::numbers::pi / 360);
  const double width_mm = g.cells_per_track * pitch_mm;
  const auto columns = static_cast<std::size_t>(std::ceil((width_mm + pitch_mm) * px_per_mm)) + 1;
  std::vector<float> widest(columns), depth(columns);
  for (std::uint32_t t = 0; t < g.tracks; ++t) {
    std::fill(widest.begin(), widest.end(), 0.0f);
    std::fill(depth.begin(), depth.end(), 0.0f);
    const std::uint64_t first_cell = static_cast<std::uint64_t>(t) * g.cells_per_track;
    const std::uint64_t begin = first_sample_of_cell(first_cell, g.cell_rate_hz);
    const std::uint64_t end = std::min<std::uint64_t>(first_sample_of_cell(first_cell + g.cells_per_track, g.cell_rate_hz), cut.size());
    const double shift = g.stagger && t % 2 == 1 ? 0.5 : 0;
    for (std::uint64_t n = begin; n < end; ++n) {
      if (!(cut[n] > 0)) continue;
      const CellPosition p = cell_position(n, g.cell_rate_hz);
      const double x_mm = (static_cast<double>(p.cell - first_cell) + p.fraction + shift) * pitch_mm;
      const auto col = std::min(columns - 1, static_cast<std::size_t>(x_mm * px_per_mm));
      const float w = static_cast<float>(2 * half_width * cut[n] / 1000);
      widest[col] = std::max(widest[col], w);
      depth[col] = std::max(depth[col], cut[n]);
    }
    const double centre = -(t + 0.5) * track_mm;  // row 0 at the top
    for (std::size_t c = 0; c < columns; ++c) {
      if (widest[c] <= 0) continue;
      const double grey = 0.85 * (1 - std::min(1.0, depth[c] / deepest_um));
      cairo_set_source_rgb(cr, grey, grey, grey);
      cairo_rectangle(cr, c / px_per_mm, centre - widest[c] / 2, 1 / px_per_mm, widest[c]);
      cairo_fill(cr);
    }
  }
}

void title(Canvas& canvas, const char* text, double x_px) {
  cairo_t* cr = canvas.cr();
  cairo_identity_matrix(cr);
  cairo_reset_clip(cr);
  cairo_set_source_rgb(cr, 0.1, 0.1, 0.1);
  cairo_select_font_face(cr, "sans-serif", CAIRO_FONT_SLANT_NORMAL, CAIRO_FONT_WEIGHT_BOLD);
  cairo_set_font_size(cr, 15);
  cairo_move_to(cr, x_px, 19);
  cairo_show_text(cr, text);
}

}  // namespace

void write_gravure_preview(const GravureLayout& g, std::span<const float> intended, std::span<const float> engraved,
                           const std::string& path) {
  const double width_mm = (g.cells_per_track + (g.stagger ? 0.5 : 0)) * g.cell_pitch_um / 1000;
  const double height_mm = g.tracks * g.track_pitch_um / 1000;
  const double px_per_mm = std::min(kMaxPanelPx / width_mm, kMaxPanelPx / height_mm);
  const double panel_w = width_mm * px_per_mm, panel_h = height_mm * px_per_mm;
  Canvas canvas(path, static_cast<int>(std::ceil(2 * panel_w + 3 * kGapPx)),
                static_cast<int>(std::ceil(panel_h + kTitlePx + kGapPx)));
  float deepest = 1;
  for (float c : intended) deepest = std::max(deepest, c);
  Box view;
  view.add(Point(0, -height_mm));
  view.add(Point(width_mm, 0));
  canvas.set_view(view, kGapPx, kTitlePx, px_per_mm);
  draw_panel(canvas, g, intended, px_per_mm, deepest);
  canvas.set_view(view, 2 * kGapPx + panel_w, kTitlePx, px_per_mm);
  draw_panel(canvas, g, engraved, px_per_mm, deepest);
  title(canvas, "intended", kGapPx);
  title(canvas, "engraved", 2 * kGapPx + panel_w);
  canvas.finish();
}

}  // namespace mark

#include "marker/preview/mark_preview.hpp"

#include <algorithm>
#include <cmath>
#include <memory>
#include <vector>

#include "marker/preview/cairo_path.hpp"
#include "marker/preview/canvas.hpp"

namespace mark {
namespace {

constexpr double kMaxWidthPx = 2400, kMaxHeightPx = 1600;

constexpr Rgb kJump{0.9, 0.5, 0.1}, kJoin{0.2, 0.6, 0.9}, kRun{0.1, 0.3, 0.9}, kDwell{0.9, 0.1, 0.1},
    kDose{0.35, 0.35, 0.35};

std::vector<LegendEntry> legend(const Plan& plan) {
  auto has = [&](CommandRole role) {
    for (const Command& c : plan.commands)
      if (c.role == role && c.kind != CommandKind::dwell) return true;
    return false;
  };
  std::vector<LegendEntry> l{{"dose the beam left (darker = more)", kDose, LegendMark::area}};
  if (has(CommandRole::jump)) l.push_back({"jumps (laser off)", kJump, LegendMark::dashed});
  if (has(CommandRole::run_in) || has(CommandRole::run_out))
    l.push_back({"blanking run-in / run-out (laser off)", kRun, LegendMark::line});
  if (has(CommandRole::blank_join)) l.push_back({"blanking joins (laser off)", kJoin, LegendMark::dashed});
  for (const Command& c : plan.commands)
    if (c.kind == CommandKind::dwell) {
      l.push_back({"delay dwells", kDwell, LegendMark::dot});
      break;
    }
  return l;
}


// The dose under `view` as an image of the canvas's size: each image pixel shows the largest
// dose of the raster pixels it covers, scaled to the raster's largest pixel.
void paint_dose(Canvas& canvas, const Box& view, const DoseRaster& dose, int w, int h) {
  const double top = dose.max_pixel();
  if (dose.empty() || !(top > 0)) return;
  cairo_surface_t* img = cairo_image_surface_create(CAIRO_FORMAT_RGB24, w, h);
  unsigned char* data = cairo_image_surface_get_data(img);
  const int stride = cairo_image_surface_get_stride(img);
  const double mm_per_px = view.width() / w, pix = dose.pixel_mm();
  for (int row = 0; row < h; ++row) {
    const double y1 = view.max.y() - row * mm_per_px, y0 = y1 - mm_per_px;
    const auto iy0 = static_cast<std::int64_t>(std::floor(y0 / pix));
    const auto iy1 = std::max(iy0, static_cast<std::int64_t>(std::ceil(y1 / pix)) - 1);
    auto* line = reinterpret_cast<std::uint32_t*>(data + row * stride);
    for (int col = 0; col < w; ++col) {
      const double x0 = view.min.x() + col * mm_per_px, x1 = x0 + mm_per_px;
      const auto ix0 = static_cast<std::int64_t>(std::floor(x0 / pix));
      const auto ix1 = std::max(ix0, static_cast<std::int64_t>(std::ceil(x1 / pix)) - 1);
      double d = 0;
      for (std::int64_t iy = iy0; iy <= iy1; ++iy)
        for (std::int64_t ix = ix0; ix <= ix1; ++ix) d = std::max(d, dose.pixel(ix, iy));
      const auto grey = static_cast<std::uint32_t>(255.0 * (1.0 - std::min(1.0, d / top)));
      line[col] = (grey << 16) | (grey << 8) | grey;
    }
  }
  cairo_surface_mark_dirty(img);
  cairo_t* cr = canvas.cr();
  cairo_save(cr);
  cairo_translate(cr, view.min.x(), view.max.y());  // image origin: top-left of the view
  cairo_scale(cr, mm_per_px, -mm_per_px);
  cairo_set_source_surface(cr, img, 0, 0);
  cairo_pattern_set_filter(cairo_get_source(cr), CAIRO_FILTER_NEAREST);
  cairo_paint(cr);
  cairo_restore(cr);
  cairo_surface_destroy(img);
}

void stroke_role(Canvas& canvas, const Plan& plan, CommandRole role, const Rgb& colour, bool dashed) {
  cairo_t* cr = canvas.cr();
  bool any = false;
  for (const Command& c : plan.commands)
    if (c.role == role && c.kind != CommandKind::dwell) append_element(cr, c.path), any = true;
  if (!any) return;
  cairo_set_source_rgba(cr, colour.r, colour.g, colour.b, 0.8);
  canvas.set_line_px(1.0);
  canvas.set_dash_px(dashed ? 4 : 0, 3);
  cairo_stroke(cr);
  canvas.set_dash_px(0, 0);
}

// The picture drawn on a canvas for `path` (its extension picks SVG or PNG), not yet encoded.
std::unique_ptr<Canvas> draw_mark_preview(const Plan& plan, const DoseRaster& dose, const std::string& path) {
  const Box bounds = plan.bounds();
  const Box view = bounds.grown(std::max(0.05, 0.03 * std::max(bounds.width(), bounds.height())));
  // At most one image pixel per raster pixel, and no larger than the size limits.
  const double scale = std::min({1.0 / dose.pixel_mm(), kMaxWidthPx / view.width(),
                                 kMaxHeightPx / view.height()});
  auto drawn = std::make_unique<Canvas>(path, view, scale, legend(plan));
  Canvas& canvas = *drawn;
  const int w = static_cast<int>(std::ceil(view.width() * scale));
  const int h = static_cast<int>(std::ceil(view.height() * scale));
  paint_dose(canvas, view, dose, w, h);
  stroke_role(canvas, plan, CommandRole::jump, kJump, true);
  stroke_role(canvas, plan, CommandRole::blank_join, kJoin, true);
  stroke_role(canvas, plan, CommandRole::run_in, kRun, false);
  stroke_role(canvas, plan, CommandRole::run_out, kRun, false);
  cairo_t* cr = canvas.cr();
  for (const Command& c : plan.commands)
    if (c.kind == CommandKind::dwell) {
      cairo_new_sub_path(cr);
      cairo_arc(cr, c.start().x(), c.start().y(), 2.0 / scale, 0, 2 * M_PI);
    }
  cairo_set_source_rgba(cr, kDwell.r, kDwell.g, kDwell.b, 0.7);
  cairo_fill(cr);
  return drawn;
}

}  // namespace

void write_mark_preview(const Plan& plan, const DoseRaster& dose, const std::string& path) {
  draw_mark_preview(plan, dose, path)->finish();
}

std::string encode_mark_preview(const Plan& plan, const DoseRaster& dose, const std::string& format) {
  return draw_mark_preview(plan, dose, format)->encoded();
}

}  // namespace mark

#include "marker/preview/canvas.hpp"

#include <cairo-svg.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "base/error.hpp"
#include "marker/output/output_file.hpp"

namespace mark {
namespace {

// Cairo writes SVG and PNG through this into memory; the file is written whole at the end.
cairo_status_t append_bytes(void* closure, const unsigned char* data, unsigned int length) {
  static_cast<std::string*>(closure)->append(reinterpret_cast<const char*>(data), length);
  return CAIRO_STATUS_SUCCESS;
}

}  // namespace

Canvas::Canvas(const std::string& path, const Box& view, double px_per_mm, std::vector<LegendEntry> legend)
    : Canvas(path, static_cast<int>(std::ceil(view.width() * px_per_mm)),
             static_cast<int>(std::ceil(view.height() * px_per_mm)), std::move(legend)) {
  set_view(view, 0, 0, px_per_mm);
}

Canvas::Canvas(const std::string& path, int w, int h, std::vector<LegendEntry> legend)
    : path_(path), legend_(std::move(legend)), px_per_mm_(1) {
  const std::string ext = output_format(path, {".svg", ".png"});  // "-": SVG to standard output
  if (ext == ".png") {
    png_ = true;
  } else if (ext != ".svg") {
    throw InputError("preview file '" + path + "': the name must end in .svg or .png");
  }
  // Wide enough for the legend to read, whatever the picture's scale.
  w = std::max(320, w);
  h = std::max(1, h);
  width_px_ = w;
  height_px_ = h;
  h += legend_height_px(legend_, w);
  if (w > 20000 || h > 20000)
    throw InputError("preview file '" + path + "': " + std::to_string(w) + "×" + std::to_string(h) +
                     " px is too large; lower the scale");
  surface_ = png_ ? cairo_image_surface_create(CAIRO_FORMAT_ARGB32, w, h)
                  : cairo_svg_surface_create_for_stream(append_bytes, &bytes_, w, h);
  if (cairo_surface_status(surface_) != CAIRO_STATUS_SUCCESS) {
    cairo_surface_destroy(surface_);
    surface_ = nullptr;
    throw InputError("preview file '" + path + "': cannot be created");
  }
  cr_ = cairo_create(surface_);
  cairo_set_source_rgb(cr_, 1, 1, 1);
  cairo_paint(cr_);
  cairo_set_line_cap(cr_, CAIRO_LINE_CAP_ROUND);
  cairo_set_line_join(cr_, CAIRO_LINE_JOIN_ROUND);
}

void Canvas::set_view(const Box& view, double x_px, double y_px, double px_per_mm) {
  px_per_mm_ = px_per_mm;
  std::erase_if(panels_, [&](const PanelScale& p) { return p.x_px == x_px; });
  panels_.push_back({x_px, std::min(view.width() * px_per_mm, width_px_ - x_px), px_per_mm});
  cairo_identity_matrix(cr_);
  cairo_reset_clip(cr_);
  cairo_rectangle(cr_, x_px, y_px, view.width() * px_per_mm, view.height() * px_per_mm);
  cairo_clip(cr_);
  // Field millimetres, y up.
  cairo_translate(cr_, x_px, y_px);
  cairo_scale(cr_, px_per_mm, -px_per_mm);
  cairo_translate(cr_, -view.min.x(), -view.max.y());
}

Canvas::~Canvas() {
  if (cr_) cairo_destroy(cr_);
  if (surface_) cairo_surface_destroy(surface_);
}

void Canvas::set_line_px(double px) { cairo_set_line_width(cr_, px / px_per_mm_); }

void Canvas::set_dash_px(double on_px, double off_px) {
  if (on_px <= 0) {
    cairo_set_dash(cr_, nullptr, 0, 0);
    return;
  }
  const double d[2] = {on_px / px_per_mm_, off_px / px_per_mm_};
  cairo_set_dash(cr_, d, 2, 0);
}

void Canvas::finish() { write_file_whole(path_, encoded()); }

std::string Canvas::encoded() {
  draw_legend(cr_, panels_, legend_, height_px_, width_px_);
  cairo_surface_flush(surface_);
  cairo_status_t status = CAIRO_STATUS_SUCCESS;
  if (png_) {
    status = cairo_surface_write_to_png_stream(surface_, append_bytes, &bytes_);
  } else {
    cairo_surface_finish(surface_);
    status = cairo_surface_status(surface_);
  }
  if (status != CAIRO_STATUS_SUCCESS)
    throw InputError("preview file '" + path_ + "': " + cairo_status_to_string(status));
  return std::move(bytes_);
}

}  // namespace mark

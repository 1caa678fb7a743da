#include "marker/preview/canvas.hpp"

#include <cairo-svg.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "fonts/error.hpp"

namespace mark {
namespace {

bool ends_with(const std::string& s, const std::string& suffix) {
  if (s.size() < suffix.size()) return false;
  std::string tail = s.substr(s.size() - suffix.size());
  std::transform(tail.begin(), tail.end(), tail.begin(), ::tolower);
  return tail == suffix;
}

}  // namespace

Canvas::Canvas(const std::string& path, const Box& view, double px_per_mm)
    : Canvas(path, static_cast<int>(std::ceil(view.width() * px_per_mm)),
             static_cast<int>(std::ceil(view.height() * px_per_mm))) {
  set_view(view, 0, 0, px_per_mm);
}

Canvas::Canvas(const std::string& path, int w, int h) : path_(path), px_per_mm_(1) {
  if (ends_with(path, ".png")) {
    png_ = true;
  } else if (!ends_with(path, ".svg")) {
    throw InputError("preview file '" + path + "': the name must end in .svg or .png");
  }
  w = std::max(1, w);
  h = std::max(1, h);
  if (w > 20000 || h > 20000)
    throw InputError("preview file '" + path + "': " + std::to_string(w) + "×" + std::to_string(h) +
                     " px is too large; lower the scale");
  surface_ = png_ ? cairo_image_surface_create(CAIRO_FORMAT_ARGB32, w, h)
                  : cairo_svg_surface_create(temp_path().c_str(), w, h);
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
  // An unfinished preview leaves nothing behind.
  if (!finished_) std::remove(temp_path().c_str());
}

std::string Canvas::temp_path() const { return path_ + ".part"; }

void Canvas::set_line_px(double px) { cairo_set_line_width(cr_, px / px_per_mm_); }

void Canvas::set_dash_px(double on_px, double off_px) {
  if (on_px <= 0) {
    cairo_set_dash(cr_, nullptr, 0, 0);
    return;
  }
  const double d[2] = {on_px / px_per_mm_, off_px / px_per_mm_};
  cairo_set_dash(cr_, d, 2, 0);
}

void Canvas::finish() {
  cairo_surface_flush(surface_);
  cairo_status_t status = CAIRO_STATUS_SUCCESS;
  // Written under a temporary name and renamed, so a failed write never leaves half a file.
  if (png_) {
    status = cairo_surface_write_to_png(surface_, temp_path().c_str());
  } else {
    cairo_surface_finish(surface_);
    status = cairo_surface_status(surface_);
  }
  if (status != CAIRO_STATUS_SUCCESS)
    throw InputError("preview file '" + path_ + "': " + cairo_status_to_string(status));
  if (std::rename(temp_path().c_str(), path_.c_str()) != 0)
    throw InputError("preview file '" + path_ + "': cannot be written");
  finished_ = true;
}

}  // namespace mark

#pragma once
// A Cairo drawing surface in field millimetres (y up) that writes itself as SVG or PNG, chosen by
// the output file's extension. Shared by every preview (layout, mark, gcode, peen). Under the
// picture a strip shows a scale bar for each view and the preview's legend (legend.hpp).
#include <cairo.h>

#include <string>
#include <vector>

#include "fonts/box.hpp"
#include "marker/preview/legend.hpp"

namespace mark {

class Canvas {
 public:
  // One view: `view` is the region of the field to show (mm); px_per_mm its scale.
  Canvas(const std::string& path, const Box& view, double px_per_mm, std::vector<LegendEntry> legend = {});
  // A blank picture of the given size for several views (panels), each set with set_view.
  Canvas(const std::string& path, int width_px, int height_px, std::vector<LegendEntry> legend = {});
  ~Canvas();
  Canvas(const Canvas&) = delete;
  Canvas& operator=(const Canvas&) = delete;

  cairo_t* cr() { return cr_; }
  // Draw `view` (mm, y up) into the panel whose top-left corner is at (x_px, y_px), clipped to it.
  void set_view(const Box& view, double x_px, double y_px, double px_per_mm);
  double px_per_mm() const { return px_per_mm_; }
  // Line width in pixels regardless of the mm scale.
  void set_line_px(double px);
  void set_dash_px(double on_px, double off_px);
  // Writes the file whole (marker/output/output_file.hpp); throws InputError naming it on failure.
  void finish();
  // The encoded picture instead of the file (an HTTP answer); `path` named only its format.
  std::string encoded();

 private:
  std::string path_;
  std::vector<LegendEntry> legend_;
  std::vector<PanelScale> panels_;  // one per view, for the scale bars
  int width_px_ = 0, height_px_ = 0;  // the picture above the legend strip
  std::string bytes_;  // the encoded picture, written to path_ by finish()
  bool png_ = false;
  double px_per_mm_;
  cairo_surface_t* surface_ = nullptr;
  cairo_t* cr_ = nullptr;
};

}  // namespace mark

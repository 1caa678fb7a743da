#pragma once
// The strip under every preview: a scale bar under each panel (a round length in mm at that
// panel's scale) and a legend saying what each colour and line style means. Drawn in pixels
// below the picture, so it never covers what it explains.
#include <cairo.h>

#include <string>
#include <vector>

namespace mark {

struct Rgb {
  double r = 0, g = 0, b = 0;
};

enum class LegendMark { line, dashed, area, dot };

struct LegendEntry {
  std::string label;
  Rgb colour;
  LegendMark mark = LegendMark::line;
};

// A panel of the picture: where it starts (pixels from the left) and its scale.
struct PanelScale {
  double x_px = 0;
  double width_px = 0;
  double px_per_mm = 1;
};

// Height the strip needs for these entries in a picture `width_px` wide.
int legend_height_px(const std::vector<LegendEntry>& entries, int width_px);

// Draws the strip from `top_px` down (device pixels).
void draw_legend(cairo_t* cr, const std::vector<PanelScale>& panels, const std::vector<LegendEntry>& entries,
                 double top_px, int width_px);

// The scale bar's length for a panel: the largest of 1, 2, 5 × 10^k mm no longer than `max_px`.
double scale_bar_mm(double px_per_mm, double max_px);

}  // namespace mark

// What a preview tells its reader besides the marks, read back from the PNG: the scale bar is as
// long as its round length at the drawing's own scale (measured on the 110 mm field frame), the
// legend shows the colours the picture uses, and a circular fitting's circle is drawn as a guide.
#include <cairo.h>
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <filesystem>
#include <string>

#include "../cli_runner.hpp"
#include "marker/preview/legend.hpp"

namespace mark {
namespace {

namespace fs = std::filesystem;

struct Png {
  cairo_surface_t* s = nullptr;
  int w = 0, h = 0;
  explicit Png(const std::string& path) : s(cairo_image_surface_create_from_png(path.c_str())) {
    w = cairo_image_surface_get_width(s);
    h = cairo_image_surface_get_height(s);
  }
  ~Png() { cairo_surface_destroy(s); }
  std::uint32_t rgb(int x, int y) const {
    if (x < 0 || y < 0 || x >= w || y >= h) return 0xFFFFFF;
    const auto* row = reinterpret_cast<const std::uint32_t*>(cairo_image_surface_get_data(s) +
                                                            y * cairo_image_surface_get_stride(s));
    return row[x] & 0xFFFFFF;
  }
  // Longest run of pixels darker than `level` (all channels) in row y.
  int dark_run(int y, unsigned level) const {
    int best = 0, run = 0;
    for (int x = 0; x < w; ++x) {
      const std::uint32_t c = rgb(x, y);
      const bool dark = ((c >> 16) & 0xFF) < level && ((c >> 8) & 0xFF) < level && (c & 0xFF) < level;
      run = dark ? run + 1 : 0;
      best = std::max(best, run);
    }
    return best;
  }
  int count(std::uint32_t colour, int y0, int y1) const {
    int n = 0;
    for (int y = y0; y < y1; ++y)
      for (int x = 0; x < w; ++x) n += rgb(x, y) == colour;
    return n;
  }
};

// A colour as cairo stores it in a PNG pixel.
std::uint32_t as_drawn(double r, double g, double b) {
  cairo_surface_t* s = cairo_image_surface_create(CAIRO_FORMAT_RGB24, 1, 1);
  cairo_t* cr = cairo_create(s);
  cairo_set_source_rgb(cr, r, g, b);
  cairo_paint(cr);
  cairo_destroy(cr);
  cairo_surface_flush(s);
  const std::uint32_t c = *reinterpret_cast<const std::uint32_t*>(cairo_image_surface_get_data(s)) & 0xFFFFFF;
  cairo_surface_destroy(s);
  return c;
}

std::string preview(const std::string& name, std::vector<std::string> extra) {
  const fs::path out = test::fresh_temp_file("marker_preview_annotation_test", name);
  std::vector<std::string> args = {"preview", "SN 0042", "--height", "15", "--x", "-50", "-o", out.string()};
  args.insert(args.end(), extra.begin(), extra.end());
  const test::CliResult r = test::run_cli(args);
  EXPECT_EQ(r.code, 0) << r.err;
  return out.string();
}

TEST(PreviewAnnotation, ScaleBarMatchesTheDrawingsScale) {
  const Png png(preview("scale.png", {}));
  ASSERT_GT(png.w, 0);
  // The field frame's top edge: the longest dark run in the top half, 110 mm long.
  int frame_px = 0, frame_row = 0;
  for (int y = 0; y < png.h / 2; ++y)
    if (const int run = png.dark_run(y, 100); run > frame_px) frame_px = run, frame_row = y;
  const double px_per_mm = (frame_px - 1.5) / 110.0;  // the frame's line is 1.5 px wide
  ASSERT_GT(px_per_mm, 5) << "frame at row " << frame_row;
  // The scale bar: the longest black run below the picture (the legend strip's first row).
  int bar_px = 0;
  for (int y = png.h - 80; y < png.h; ++y) bar_px = std::max(bar_px, png.dark_run(y, 40));
  const double bar_mm = scale_bar_mm(px_per_mm, 0.3 * png.w);
  EXPECT_NEAR(bar_px, bar_mm * px_per_mm, 3.0) << bar_mm << " mm at " << px_per_mm << " px/mm";
  EXPECT_GE(bar_mm * px_per_mm, 0.3 * png.w / 2.5) << "a round length between 40 % and 100 % of the room";
}

TEST(PreviewAnnotation, LegendShowsTheColoursInThePicture) {
  const Png png(preview("legend.png", {}));
  // Marks are drawn in rgb(0.05, 0.15, 0.55); the legend's swatch is in the strip below the
  // picture, whose top is the light grey separator line.
  const std::uint32_t mark_blue = as_drawn(0.05, 0.15, 0.55);
  int strip_top = png.h - 1;
  while (strip_top > 0 && png.dark_run(strip_top, 220) < png.w - 2) --strip_top;
  ASSERT_GT(strip_top, png.h / 2);
  EXPECT_GT(png.count(mark_blue, 0, strip_top), 100) << "the marks";
  EXPECT_GE(png.count(mark_blue, strip_top, png.h), 26) << "the legend's swatch for them";
}

TEST(PreviewAnnotation, CircularFittingDrawsItsCircle) {
  // Grey dashes on the lower half of the circle, where no letter stands. The text is wider than
  // 40 % of the field, so the preview is one panel: the field grown by 2 % on 1200 px.
  auto guide_pixels = [](const Png& png) {
    const double px_per_mm = 1200.0 / (110 * 1.04), top_mm = 55 * 1.04, left_mm = -55 * 1.04;
    int grey = 0;
    for (int k = 0; k < 180; ++k) {
      const double a = M_PI + k * M_PI / 180;
      const int x = static_cast<int>(std::lround((40 * std::cos(a) - left_mm) * px_per_mm));
      const int y = static_cast<int>(std::lround((top_mm - 40 * std::sin(a)) * px_per_mm));
      bool found = false;
      for (int dy = -1; dy <= 1 && !found; ++dy)
        for (int dx = -1; dx <= 1 && !found; ++dx) {
          const std::uint32_t c = png.rgb(x + dx, y + dy);
          const int r = (c >> 16) & 0xFF, g = (c >> 8) & 0xFF, b = c & 0xFF;
          found = r < 220 && std::abs(r - g) < 8 && std::abs(g - b) < 8;
        }
      grey += found;
    }
    return grey;
  };
  const std::string circle = test::fresh_temp_file("marker_preview_annotation_test", "circle.png").string();
  const test::CliResult r = test::run_cli({"preview", "SEAL OF QUALITY", "--circle", "0,0,40", "--height", "8", "-o", circle});
  ASSERT_EQ(r.code, 0) << r.err;
  const Png with(circle);
  EXPECT_GT(guide_pixels(with), 90) << "dashes 6 px on, 4 px off: about 60 % of the circle";
  const Png without(preview("no_circle.png", {}));
  EXPECT_LT(guide_pixels(without), 10);
}

}  // namespace
}  // namespace mark

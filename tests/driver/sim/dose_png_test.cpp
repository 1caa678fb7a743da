// The dose image: a PNG of the used area, dark where the dose is high, y up (decoded back from
// the bytes encode_dose_png makes; the file is written by marker/output, tested there).
#include "driver/sim/dose_png.hpp"

#include <cairo.h>
#include <gtest/gtest.h>

#include <cstdint>
#include <algorithm>
#include <string>


namespace mark {
namespace {

// The encoded PNG read back through cairo.
cairo_surface_t* decode(const std::string& png) {
  struct Reader {
    const std::string& bytes;
    std::size_t at = 0;
  } reader{png};
  return cairo_image_surface_create_from_png_stream(
      [](void* closure, unsigned char* data, unsigned int length) {
        auto* r = static_cast<Reader*>(closure);
        if (r->bytes.size() - r->at < length) return CAIRO_STATUS_READ_ERROR;
        std::copy_n(r->bytes.data() + r->at, length, data);
        r->at += length;
        return CAIRO_STATUS_SUCCESS;
      },
      &reader);
}

std::uint32_t grey_at(cairo_surface_t* s, int x, int y) {
  const auto* row = cairo_image_surface_get_data(s) + y * cairo_image_surface_get_stride(s);
  return reinterpret_cast<const std::uint32_t*>(row)[x] & 0xff;
}

TEST(DosePng, WritesTheUsedAreaDarkWhereDosed) {
  DoseRaster dose(0.005);
  dose.deposit_segment({0, 0}, {0.5, 0}, 1.0);       // horizontal line at the bottom
  dose.deposit_segment({0, 0.2}, {0, 0.3}, 0.2);     // vertical line above its left end, same mm dose
  cairo_surface_t* img = decode(encode_dose_png(dose, {.margin_px = 4}));
  ASSERT_EQ(cairo_surface_status(img), CAIRO_STATUS_SUCCESS);
  const int w = cairo_image_surface_get_width(img), h = cairo_image_surface_get_height(img);
  // Tiles of 64 px cover 0..0.5 mm × 0..0.3 mm: 2 × 1 tiles (one tile row, y 0..0.315 mm).
  EXPECT_EQ(w, 2 * 64 + 8);
  EXPECT_EQ(h, 1 * 64 + 8);
  cairo_surface_flush(img);
  // Pixel (ix, iy) → image (4 + ix, h − 1 − 4 − iy). The horizontal line is dark at iy = 0,
  // the vertical one at ix = 0 around iy = 50; the background is white.
  EXPECT_LT(grey_at(img, 4 + 50, h - 1 - 4 - 0), 200u);
  EXPECT_LT(grey_at(img, 4 + 0, h - 1 - 4 - 50), 200u);
  EXPECT_EQ(grey_at(img, 4 + 50, h - 1 - 4 - 40), 255u);
  EXPECT_EQ(grey_at(img, 0, 0), 255u);
  cairo_surface_destroy(img);
}

TEST(DosePng, DownsamplesLargeRasters) {
  DoseRaster dose(0.005);
  dose.deposit_segment({0, 0}, {20, 0}, 1.0);  // 4000 px long
  cairo_surface_t* img = decode(encode_dose_png(dose, {.margin_px = 0, .max_side_px = 1000}));
  ASSERT_EQ(cairo_surface_status(img), CAIRO_STATUS_SUCCESS);
  // 63 tiles = 4032 px wide; the smallest integer factor that fits 1000 is 5.
  EXPECT_EQ(cairo_image_surface_get_width(img), 4032 / 5 + 1);
  cairo_surface_destroy(img);
}

}  // namespace
}  // namespace mark

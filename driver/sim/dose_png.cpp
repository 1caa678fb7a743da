#include "driver/sim/dose_png.hpp"

#include <cairo.h>

#include <algorithm>
#include <cmath>
#include <cstdint>

#include "driver/device_error.hpp"

namespace mark {

namespace {

cairo_status_t append_bytes(void* closure, const unsigned char* data, unsigned int length) {
  static_cast<std::string*>(closure)->append(reinterpret_cast<const char*>(data), length);
  return CAIRO_STATUS_SUCCESS;
}

}  // namespace

std::string encode_dose_png(const DoseRaster& dose, DosePngOptions options) {
  std::int64_t ix0 = 0, iy0 = 0, ix1 = 0, iy1 = 0;
  if (!dose.bounds(ix0, iy0, ix1, iy1)) ix0 = iy0 = ix1 = iy1 = 0;
  const std::int64_t w_px = ix1 - ix0 + 1, h_px = iy1 - iy0 + 1;
  // Downsample by an integer factor (keeping the maximum of each block) to fit max_side_px.
  const std::int64_t limit = std::max(1, options.max_side_px - 2 * options.margin_px);
  const std::int64_t f = std::max<std::int64_t>(1, (std::max(w_px, h_px) + limit - 1) / limit);
  const int m = std::max(0, options.margin_px);
  const int w = static_cast<int>((w_px + f - 1) / f) + 2 * m;
  const int h = static_cast<int>((h_px + f - 1) / f) + 2 * m;

  cairo_surface_t* surface = cairo_image_surface_create(CAIRO_FORMAT_RGB24, w, h);
  if (cairo_surface_status(surface) != CAIRO_STATUS_SUCCESS) {
    cairo_surface_destroy(surface);
    throw DeviceError("dose image: cannot allocate " + std::to_string(w) + "×" + std::to_string(h) +
                      " pixels");
  }
  cairo_surface_flush(surface);
  unsigned char* data = cairo_image_surface_get_data(surface);
  const int stride = cairo_image_surface_get_stride(surface);
  const double peak = std::max(dose.max_pixel(), 1e-300);

  for (int row = 0; row < h; ++row) {
    auto* line = reinterpret_cast<std::uint32_t*>(data + static_cast<std::ptrdiff_t>(row) * stride);
    for (int col = 0; col < w; ++col) {
      double d = 0;
      const std::int64_t bx = col - m, by = (h - 1 - row) - m;  // y up in the image
      if (bx >= 0 && by >= 0) {
        for (std::int64_t sy = 0; sy < f; ++sy)
          for (std::int64_t sx = 0; sx < f; ++sx)
            d = std::max(d, dose.pixel(ix0 + bx * f + sx, iy0 + by * f + sy));
      }
      const auto g = static_cast<std::uint32_t>(std::lround(255.0 * (1.0 - std::min(1.0, d / peak))));
      line[col] = (g << 16) | (g << 8) | g;
    }
  }
  cairo_surface_mark_dirty(surface);
  std::string png;
  const cairo_status_t status = cairo_surface_write_to_png_stream(surface, append_bytes, &png);
  cairo_surface_destroy(surface);
  if (status != CAIRO_STATUS_SUCCESS)
    throw DeviceError(std::string("dose image: cannot encode (") + cairo_status_to_string(status) + ")");
  return png;
}

}  // namespace mark

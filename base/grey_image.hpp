#pragma once
// A grey picture with its scale and where it lies on the part: what a camera delivers and what a
// code verifier grades. A plain value type below every stage, so the simulator that takes the
// picture (driver/sim/) and the verifier that reads it (marker/codes/) share it without knowing
// each other.
#include <cstdint>
#include <vector>

namespace mark {

struct GreyImage {
  int width = 0;
  int height = 0;
  double pixel_mm = 0;                // on the part
  // The field point (mm, y up) at the centre of pixel (0, 0), the top-left pixel: column x lies
  // at x0_mm + x·pixel_mm, row y at top_mm − y·pixel_mm.
  double x0_mm = 0, top_mm = 0;
  std::vector<std::uint8_t> grey;     // row 0 at the top, 0 black .. 255 white

  std::uint8_t at(int x, int y) const { return grey[static_cast<std::size_t>(y) * width + x]; }
  bool empty() const { return width <= 0 || height <= 0; }
  // Pixel coordinates (column, row; fractional, pixel centres at whole numbers) of a field point.
  double column_of(double x_mm) const { return (x_mm - x0_mm) / pixel_mm; }
  double row_of(double y_mm) const { return (top_mm - y_mm) / pixel_mm; }
};

}  // namespace mark

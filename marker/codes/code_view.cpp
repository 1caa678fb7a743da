#include "marker/codes/code_view.hpp"

#include <cmath>

#include "marker/codes/module_grid.hpp"

namespace mark {

GreyImage code_frame_view(const GreyImage& picture, const PlacedCode& code, double margin_mm) {
  // The symbol and its quiet zone in the code frame.
  const double q = code.quiet_modules * code.module_mm;
  const bool linear = is_linear(code.matrix.symbology);
  const double x0 = -q - margin_mm, x1 = code.width_mm + q + margin_mm;
  const double y0 = (linear ? 0 : -q) - margin_mm, y1 = code.height_mm + (linear ? 0 : q) + margin_mm;
  GreyImage out;
  out.pixel_mm = picture.pixel_mm;
  out.width = static_cast<int>(std::ceil((x1 - x0) / out.pixel_mm)) + 1;
  out.height = static_cast<int>(std::ceil((y1 - y0) / out.pixel_mm)) + 1;
  out.x0_mm = x0;
  out.top_mm = y1;
  out.grey.resize(static_cast<std::size_t>(out.width) * out.height);
  for (int row = 0; row < out.height; ++row)
    for (int col = 0; col < out.width; ++col) {
      const Point field = code.to_field * Point(x0 + col * out.pixel_mm, y1 - row * out.pixel_mm);
      const double v = sample(picture, Eigen::Vector2d(picture.column_of(field.x()), picture.row_of(field.y())));
      out.grey[static_cast<std::size_t>(row) * out.width + col] = static_cast<std::uint8_t>(std::lround(v));
    }
  return out;
}

}  // namespace mark

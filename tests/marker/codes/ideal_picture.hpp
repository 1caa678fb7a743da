#pragma once
// Pictures of codes as meant, for reader and grading tests that need no laser: each pixel the
// share of its area (4 × 4 points) that falls on a dark module of `modules` placed where `code`
// puts its symbol, between a light and a dark grey; seeded Gaussian noise on top. A distortion
// moves where the picture's points fall on the code before they are looked up (a stretched,
// sheared or locally shifted symbol).
#include <cmath>
#include <functional>
#include <random>

#include "base/grey_image.hpp"
#include "marker/codes/code_marks.hpp"

namespace mark::test {

struct PictureLook {
  double pixel_mm = 0.04;
  double light = 200, dark = 40;
  double noise = 0;  // rms grey
  unsigned seed = 1;
  double margin_modules = 4;  // bare part around the quiet zone
  // Code-frame point (mm) → the code-frame point whose module colours it.
  std::function<Point(const Point&)> distort;
};

inline GreyImage ideal_picture(const PlacedCode& code, const ModuleMatrix& modules, const PictureLook& look = {}) {
  const double margin = look.margin_modules * code.module_mm;
  GreyImage img;
  img.pixel_mm = look.pixel_mm;
  img.width = static_cast<int>(std::ceil((code.bounds.max.x() - code.bounds.min.x() + 2 * margin) / look.pixel_mm));
  img.height = static_cast<int>(std::ceil((code.bounds.max.y() - code.bounds.min.y() + 2 * margin) / look.pixel_mm));
  img.x0_mm = code.bounds.min.x() - margin;
  img.top_mm = code.bounds.max.y() + margin;
  img.grey.resize(static_cast<std::size_t>(img.width) * img.height);
  const Affine to_local = code.to_field.inverse();
  const bool linear = is_linear(code.matrix.symbology);
  std::mt19937 rng(look.seed);
  std::normal_distribution<double> normal(0, 1);
  for (int y = 0; y < img.height; ++y)
    for (int x = 0; x < img.width; ++x) {
      double dark = 0;
      for (int a = 0; a < 4; ++a)
        for (int b = 0; b < 4; ++b) {
          const Point field(img.x0_mm + (x - 0.375 + 0.25 * a) * img.pixel_mm, img.top_mm - (y - 0.375 + 0.25 * b) * img.pixel_mm);
          Point p = to_local * field;
          if (look.distort) p = look.distort(p);
          const int col = static_cast<int>(std::floor(p.x() / code.module_mm));
          const int row = linear ? (p.y() >= 0 && p.y() < code.height_mm ? 0 : -1)
                                 : static_cast<int>(std::floor((code.height_mm - p.y()) / code.module_mm));
          if (row >= 0 && row < modules.rows && col >= 0 && col < modules.cols && modules.dark(row, col)) dark += 1.0 / 16;
        }
      const double g = look.light + (look.dark - look.light) * dark + look.noise * normal(rng);
      img.grey[static_cast<std::size_t>(y) * img.width + x] = static_cast<std::uint8_t>(std::lround(std::clamp(g, 0.0, 255.0)));
    }
  return img;
}

}  // namespace mark::test

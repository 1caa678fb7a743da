#include "marker/codes/synthetic_aperture.hpp"

#include <cmath>
#include <vector>

namespace mark {

GreyImage synthetic_aperture(const GreyImage& image, double diameter_px) {
  const double r = diameter_px / 2;
  if (r < 0.5) return image;
  // The disc as row offsets with their half widths, pixels whose centres lie inside.
  const int reach = static_cast<int>(std::floor(r));
  std::vector<int> half(2 * static_cast<std::size_t>(reach) + 1);
  for (int dy = -reach; dy <= reach; ++dy)
    half[static_cast<std::size_t>(dy + reach)] = static_cast<int>(std::floor(std::sqrt(r * r - dy * dy)));
  // Prefix sums per row make each disc row a difference of two sums.
  const int w = image.width, h = image.height;
  std::vector<std::int64_t> prefix(static_cast<std::size_t>(w + 1) * h, 0);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x)
      prefix[static_cast<std::size_t>(y) * (w + 1) + x + 1] =
          prefix[static_cast<std::size_t>(y) * (w + 1) + x] + image.at(x, y);
  GreyImage out = image;
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      std::int64_t sum = 0, n = 0;
      for (int dy = -reach; dy <= reach; ++dy) {
        const int yy = y + dy;
        if (yy < 0 || yy >= h) continue;
        const int hw = half[static_cast<std::size_t>(dy + reach)];
        const int x0 = std::max(0, x - hw), x1 = std::min(w - 1, x + hw);
        sum += prefix[static_cast<std::size_t>(yy) * (w + 1) + x1 + 1] - prefix[static_cast<std::size_t>(yy) * (w + 1) + x0];
        n += x1 - x0 + 1;
      }
      out.grey[static_cast<std::size_t>(y) * w + x] = static_cast<std::uint8_t>((sum + n / 2) / n);
    }
  return out;
}

}  // namespace mark

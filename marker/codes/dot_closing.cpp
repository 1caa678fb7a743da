#include "marker/codes/dot_closing.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

namespace mark {
namespace {

// Min or max of every pixel's disc of the given offsets (edge pixels repeated).
GreyImage rank_filter(const GreyImage& in, const std::vector<std::pair<int, int>>& disc, bool take_min) {
  GreyImage out = in;
  for (int y = 0; y < in.height; ++y)
    for (int x = 0; x < in.width; ++x) {
      int v = take_min ? 255 : 0;
      for (const auto& [dx, dy] : disc) {
        const int g = in.at(std::clamp(x + dx, 0, in.width - 1), std::clamp(y + dy, 0, in.height - 1));
        v = take_min ? std::min(v, g) : std::max(v, g);
      }
      out.grey[static_cast<std::size_t>(y) * in.width + x] = static_cast<std::uint8_t>(v);
    }
  return out;
}

}  // namespace

GreyImage close_marks(const GreyImage& picture, double diameter_px, bool dark_marks) {
  const double r = diameter_px / 2;
  if (r < 0.5) return picture;
  std::vector<std::pair<int, int>> disc;
  const int reach = static_cast<int>(std::floor(r));
  for (int dy = -reach; dy <= reach; ++dy)
    for (int dx = -reach; dx <= reach; ++dx)
      if (dx * dx + dy * dy <= r * r) disc.push_back({dx, dy});
  // Dark marks grow where the grey is lowest: a minimum filter, then a maximum one.
  return rank_filter(rank_filter(picture, disc, dark_marks), disc, !dark_marks);
}

}  // namespace mark

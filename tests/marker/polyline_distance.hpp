#pragma once
// Distance from a point to the nearest of a set of polylines (mm), for tests that check decoded
// board coordinates against the intended strokes.
#include <algorithm>
#include <vector>

#include "driver/vec2.hpp"

namespace mark::test {

inline double distance_to(const std::vector<std::vector<Vec2>>& lines, Vec2 p) {
  double best = 1e9;
  for (const auto& l : lines)
    for (std::size_t i = 1; i < l.size(); ++i) {
      const Vec2 a = l[i - 1], d = l[i] - a;
      const double len2 = dot(d, d);
      const double t = len2 > 0 ? std::clamp(dot(p - a, d) / len2, 0.0, 1.0) : 0.0;
      best = std::min(best, norm(p - (a + t * d)));
    }
  return best;
}

}  // namespace mark::test

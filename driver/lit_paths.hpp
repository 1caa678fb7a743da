#pragma once
// Where the beam really went while the laser was on: one polyline per continuous lit run,
// points no further apart than the recording spacing (and every run's first and last point).
#include <cstddef>
#include <vector>

#include "driver/vec2.hpp"

namespace mark {

struct LitPaths {
  std::vector<std::vector<Vec2>> runs;

  std::size_t point_count() const {
    std::size_t n = 0;
    for (const auto& r : runs) n += r.size();
    return n;
  }
};

}  // namespace mark

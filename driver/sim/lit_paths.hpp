#pragma once
// Where the beam really went while the laser was on (effective power at least half of the power
// it was last commanded to while on, so a low-power pen or a power scaled with speed counts): one polyline per
// continuous lit run, with its first and last point; in between, points about the recording
// spacing apart but never more than one integration sub-step apart, so the segments between
// them are the beam path.
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

// The dose trail keeps every bit of dose and lays it evenly along the path, however finely or
// coarsely the path is cut into pieces.
#include "driver/sim/dose_trail.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <vector>

namespace mark {
namespace {

// A 1 mm diagonal line walked in pieces of `piece_mm`, 1 unit of dose per mm.
DoseRaster walk(double piece_mm) {
  DoseRaster raster(0.005);
  DoseTrail trail(raster);
  const Vec2 a{0.1, 0.2}, d{0.6, 0.8};
  for (double u = 0; u < 1.0 - 1e-12; u += piece_mm) {
    const double v = std::min(1.0, u + piece_mm);
    trail.add(a + u * d, a + v * d, v - u);
  }
  trail.flush();
  return raster;
}

TEST(DoseTrail, KeepsAllDoseAndSpreadsItEvenly) {
  for (double piece : {0.0003, 0.001, 0.0047, 0.04}) {
    const DoseRaster r = walk(piece);
    EXPECT_NEAR(r.total(), 1.0, 1e-9) << piece;
    std::vector<double> along;
    for (double u = 0.1; u <= 0.9; u += 0.005) along.push_back(r.sum_disc({0.1 + 0.6 * u, 0.2 + 0.8 * u}, 0.015));
    const auto [lo, hi] = std::minmax_element(along.begin(), along.end());
    EXPECT_LT(*hi / *lo, 1.05) << piece;  // 3.7 % is the raster and window at this angle
    // Anti-aliased disc of 15 µm radius over a line of 1 unit/mm: ≈ 0.030 of dose.
    EXPECT_NEAR(*lo, 0.030, 0.003) << piece;
  }
}

TEST(DoseTrail, DoseAtRestCollectsOnThePoint) {
  DoseRaster raster(0.005);
  DoseTrail trail(raster);
  trail.add({1, 1}, {1, 1}, 0.25);
  trail.add({1, 1}, {1, 1}, 0.75);
  EXPECT_EQ(raster.total(), 0.0);  // nothing laid until the beam moves on or flush
  trail.flush();
  EXPECT_NEAR(raster.sum_disc({1, 1}, 0.01), 1.0, 1e-6);
}

}  // namespace
}  // namespace mark

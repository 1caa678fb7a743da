// The dose raster's tile bookkeeping around the origin, where tile indices turn negative.
#include <gtest/gtest.h>

#include "driver/sim/dose_raster.hpp"

namespace mark {
namespace {

// Tile (−1, −1) has the all-ones key; a deposit there once dereferenced an empty cache.
TEST(DoseRaster, DepositsJustBelowTheOriginLandInTileMinusOne) {
  DoseRaster raster(0.005);
  raster.deposit({-0.1, -0.1}, 2.0);
  EXPECT_NEAR(raster.sum_disc({-0.1, -0.1}, 0.02), 2.0, 1e-6);
  raster.deposit({0.1, 0.1}, 1.0);
  raster.deposit({-0.1, -0.1}, 1.0);
  EXPECT_NEAR(raster.sum_disc({-0.1, -0.1}, 0.02), 3.0, 1e-6);
  EXPECT_NEAR(raster.sum_disc({0.1, 0.1}, 0.02), 1.0, 1e-6);
  EXPECT_NEAR(raster.total(), 4.0, 1e-12);
}

}  // namespace
}  // namespace mark

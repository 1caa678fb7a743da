// The dose raster's tile bookkeeping: around the origin, where tile indices turn negative; the
// tiles reserved before a job (every deposit within the margin then finds its tile); and tiles
// kept from an earlier job, which must read as zero until deposited in.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

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

// Two strokes across the origin (negative tiles), one of them a dense arc of short segments.
std::vector<std::vector<Vec2>> strokes() {
  std::vector<Vec2> arc;
  for (int i = 0; i <= 400; ++i) {
    const double a = M_PI * i / 400;
    arc.push_back({-0.7 + 1.3 * std::cos(a), 0.2 + 1.3 * std::sin(a)});
  }
  return {{{-3.0, -1.0}, {2.5, -0.4}, {2.6, 1.9}}, arc};
}

// Every point within the margin of the strokes, the pixels' grid around them: a deposit there
// must find its tile reserved (the drain thread never allocates).
TEST(DoseRaster, ReservedTilesHoldEveryDepositWithinTheMargin) {
  const double margin = 0.3;
  DoseRaster raster(0.005);
  raster.reserve_along(strokes(), margin);
  const std::size_t reserved = raster.tiles();
  ASSERT_GT(reserved, 0u);
  for (const auto& line : strokes())
    for (std::size_t i = 0; i + 1 < line.size(); ++i)
      for (double t = 0; t <= 1; t += 0.05)
        for (double dx = -margin; dx <= margin; dx += 0.02)
          for (double dy = -margin; dy <= margin; dy += 0.02) {
            if (dx * dx + dy * dy > margin * margin) continue;
            const Vec2 p = line[i] + t * (line[i + 1] - line[i]);
            raster.deposit({p.x + dx, p.y + dy}, 1e-6);
          }
  EXPECT_EQ(raster.tiles(), reserved);
  // And not the whole bounding box: the tiles far from both strokes were left out.
  std::int64_t ix0, iy0, ix1, iy1;
  ASSERT_TRUE(raster.bounds(ix0, iy0, ix1, iy1));
  const auto box = static_cast<std::size_t>((ix1 - ix0 + 1) / DoseRaster::tile_size * (iy1 - iy0 + 1) /
                                            DoseRaster::tile_size);
  EXPECT_LT(reserved, box * 3 / 4) << reserved << " of " << box;
}

// clear() keeps the tiles for the next job: reserved again they read as zero everywhere, and a
// deposit lands on zero, not on the earlier job's dose.
TEST(DoseRaster, TilesKeptFromAnEarlierJobReadAsZero) {
  DoseRaster raster(0.005);
  raster.reserve_along(strokes(), 0.5);
  for (double x = -3; x <= 2.5; x += 0.001) raster.deposit({x, -1.0 + 0.6 * (x + 3) / 5.5}, 0.25);
  ASSERT_GT(raster.max_pixel(), 0.0);
  const std::size_t tiles = raster.tiles();

  raster.clear();
  EXPECT_TRUE(raster.empty());
  EXPECT_EQ(raster.total(), 0.0);
  raster.reserve_along(strokes(), 0.5);
  EXPECT_EQ(raster.tiles(), tiles);
  EXPECT_EQ(raster.max_pixel(), 0.0);
  EXPECT_EQ(raster.sum_disc({0.0, -0.45}, 0.1), 0.0);
  EXPECT_EQ(raster.pixel(0, -90), 0.0);
  std::int64_t ix0, iy0, ix1, iy1;
  ASSERT_TRUE(raster.bounds(ix0, iy0, ix1, iy1));
  const std::int64_t w = ix1 - ix0 + 1, h = iy1 - iy0 + 1;
  std::vector<float> all(static_cast<std::size_t>(w * h), -1.0f);
  EXPECT_TRUE(raster.copy_rect(ix0, iy0, w, h, all.data()));
  for (const float v : all) ASSERT_EQ(v, 0.0f);

  raster.deposit({0.0, -0.45}, 2.0);
  EXPECT_NEAR(raster.sum_disc({0.0, -0.45}, 0.02), 2.0, 1e-6);
  EXPECT_NEAR(raster.max_pixel(), raster.pixel(0, -90), 1e-6);
  DoseRaster sum(0.005);
  sum.add(raster);
  EXPECT_NEAR(sum.sum_disc({0.0, -0.45}, 0.02), 2.0, 1e-6);
  EXPECT_NEAR(sum.total(), 2.0, 1e-12);
}

}  // namespace
}  // namespace mark

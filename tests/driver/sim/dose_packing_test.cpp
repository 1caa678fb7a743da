// The dose raster's memory bound: past its budget of dense tiles it packs the tiles the beam left
// longest ago (PackedTile). Packing must be exact, so every reader (pixel, sum_disc, copy_rect,
// max_pixel, add) gives what an unbounded raster holding the same deposits gives, value for value.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

#include "driver/sim/dose_raster.hpp"
#include "driver/sim/packed_tile.hpp"

namespace mark {
namespace {

TEST(PackedTile, ReadsBackEveryValueExactly) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<float> dose(1e-9f, 3.0f);
  std::vector<float> dense(64 * 64, 0.0f);
  for (int i = 0; i < 600; ++i) dense[rng() % dense.size()] = dose(rng);
  dense[0] = 1.5f, dense[63] = 2.5f, dense[64 * 63] = 3.5f, dense[64 * 64 - 1] = 4.5f;  // the corners
  const PackedTile packed(dense);

  std::vector<float> back(64 * 64, -1.0f);
  packed.unpack(back);
  EXPECT_EQ(back, dense);
  for (int r = 0; r < 64; ++r)
    for (int c = 0; c < 64; ++c) ASSERT_EQ(packed.value(c, r), dense[static_cast<std::size_t>(r * 64 + c)]);
  // A run inside a row visits exactly its stored pixels, left to right.
  for (int r = 0; r < 64; r += 9) {
    std::vector<int> cols;
    packed.for_each_in_row(r, 5, 40, [&](int c, float v) {
      cols.push_back(c);
      EXPECT_EQ(v, dense[static_cast<std::size_t>(r * 64 + c)]);
    });
    std::vector<int> want;
    for (int c = 5; c <= 40; ++c)
      if (dense[static_cast<std::size_t>(r * 64 + c)] != 0.0f) want.push_back(c);
    EXPECT_EQ(cols, want) << "row " << r;
  }
  // 604 values at most: far below the 16 KiB of floats.
  EXPECT_LT(packed.bytes(), 640u + 604 * 4 + 64);
}

// A serpentine of strokes 20 mm long, like lines of text: many more tiles than the budget.
void mark_serpentine(DoseRaster& raster, double seed_shift) {
  for (int line = 0; line < 12; ++line) {
    const double y = 0.3 * line;
    const double x0 = line % 2 ? 20.0 : 0.0, x1 = line % 2 ? 0.0 : 20.0;
    raster.deposit_segment({x0, y + seed_shift}, {x1, y + 0.05 * std::sin(line)}, 1e-4 * (line + 1));
  }
}

TEST(DoseRaster, PastItsBudgetItPacksTheOldestTilesAndReadsTheSame) {
  DoseRaster unbounded(0.005);
  DoseRaster bounded(0.005, 8);
  mark_serpentine(unbounded, 0.0);
  mark_serpentine(bounded, 0.0);
  // The beam comes back over the first (packed) tiles: they are unpacked and added to.
  const auto back_over = [](DoseRaster& r) { r.deposit_segment({0.1, -0.02}, {3.0, 0.4}, 2e-3); };
  back_over(unbounded);
  back_over(bounded);

  EXPECT_LE(bounded.dense_tiles(), 8u);
  EXPECT_GT(bounded.tiles(), 200u);
  EXPECT_EQ(bounded.tiles(), unbounded.tiles());
  EXPECT_EQ(bounded.total(), unbounded.total());
  EXPECT_EQ(bounded.max_pixel(), unbounded.max_pixel());
  // A stroke's trail fills a few per cent of a tile: packed, the raster is several times smaller.
  EXPECT_LT(bounded.memory_bytes() * 5, unbounded.memory_bytes())
      << bounded.memory_bytes() << " vs " << unbounded.memory_bytes();

  std::int64_t ix0, iy0, ix1, iy1;
  ASSERT_TRUE(unbounded.bounds(ix0, iy0, ix1, iy1));
  const std::int64_t w = ix1 - ix0 + 1, h = iy1 - iy0 + 1;
  std::vector<float> a(static_cast<std::size_t>(w * h)), b(a.size());
  ASSERT_TRUE(unbounded.copy_rect(ix0, iy0, w, h, a.data()));
  ASSERT_TRUE(bounded.copy_rect(ix0, iy0, w, h, b.data()));
  EXPECT_EQ(a, b);
  // A window that starts and ends inside tiles.
  std::vector<float> wa(37 * 91), wb(wa.size());
  unbounded.copy_rect(ix0 + 70, iy0 + 3, 91, 37, wa.data());
  bounded.copy_rect(ix0 + 70, iy0 + 3, 91, 37, wb.data());
  EXPECT_EQ(wa, wb);
  for (double x = -0.1; x <= 20.1; x += 0.0371)
    for (double y : {0.0, 0.3, 0.61, 1.5, 3.3}) {
      ASSERT_EQ(bounded.sum_disc({x, y}, 0.02), unbounded.sum_disc({x, y}, 0.02)) << x << ", " << y;
      const auto ix = static_cast<std::int64_t>(std::floor(x / 0.005));
      const auto iy = static_cast<std::int64_t>(std::floor(y / 0.005));
      ASSERT_EQ(bounded.pixel(ix, iy), unbounded.pixel(ix, iy));
    }

  // add() reads packed tiles too.
  DoseRaster sum_a(0.005), sum_b(0.005, 4);
  sum_a.add(unbounded);
  sum_b.add(bounded);
  EXPECT_EQ(sum_b.sum_disc({10.0, 0.0}, 0.05), sum_a.sum_disc({10.0, 0.0}, 0.05));
  EXPECT_EQ(sum_b.max_pixel(), sum_a.max_pixel());
}

// Reserving more tiles than the budget gives each its place but only the budget in floats.
TEST(DoseRaster, AReservationPastTheBudgetHoldsOnlyTheBudgetInFloats) {
  DoseRaster raster(0.005, 16);
  std::vector<std::vector<Vec2>> lines;
  for (int line = 0; line < 12; ++line) lines.push_back({{0.0, 0.3 * line}, {20.0, 0.3 * line}});
  raster.reserve_along(lines, 0.1);
  EXPECT_GT(raster.tiles(), 16u);
  EXPECT_EQ(raster.dense_tiles(), 0u);
  EXPECT_LE(raster.memory_bytes(), 16u * 16384 + raster.tiles() * 256);
  const std::size_t reserved = raster.tiles();
  mark_serpentine(raster, 0.0);
  EXPECT_EQ(raster.tiles(), reserved);
  EXPECT_LE(raster.dense_tiles(), 16u);
  EXPECT_GT(raster.max_pixel(), 0.0);
  EXPECT_THROW(DoseRaster(0.005, 3), std::invalid_argument);
}

}  // namespace
}  // namespace mark

// Cells from an image: four exact area-averaged density values per cell along the track at any
// resolution, white outside the image, staggered tracks, and the line-work mask.
#include "marker/gravure/image_cells.hpp"

#include <gtest/gtest.h>

#include "base/error.hpp"

namespace mark {
namespace {

GrayImage image(int w, int h, std::vector<float> px) { return GrayImage{w, h, std::move(px)}; }

std::vector<CellValues> all(ImageCells& cells) {
  std::vector<CellValues> out(cells.cells());
  EXPECT_EQ(cells.next(out), out.size());
  return out;
}

GravureScreen screen(double along, double across, bool stagger = false) {
  GravureScreen s;
  s.cells_per_mm_along = along;
  s.cells_per_mm_across = across;
  s.stagger = stagger;
  return s;
}

TEST(ImageCells, OnePixelPerValue) {
  // 8 × 2 px at 4 px/mm, 1 cell/mm: two cells per track, two tracks; density = 1 − grey.
  const GrayImage img = image(8, 2, {1, 0.75f, 0.5f, 0.25f, 0, 0, 1, 1,  //
                                     0, 0, 0, 0, 1, 1, 1, 0.5f});
  ImageCells cells(img, nullptr, screen(1, 0.5), 4);
  ASSERT_EQ(cells.tracks(), 1u);  // 0.5 mm tall at 0.5 tracks/mm rounds to one track
  ImageCells rows(img, nullptr, screen(1, 2), 4);
  ASSERT_EQ(rows.tracks(), 1u);
  ImageCells fine(img, nullptr, screen(1, 4), 4);  // 0.5 mm · 4 tracks/mm = 2 tracks
  ASSERT_EQ(fine.tracks(), 2u);
  ASSERT_EQ(fine.cells_per_track(), 2u);
  const std::vector<CellValues> c = all(fine);
  const float expect[4][4] = {{0, 0.25f, 0.5f, 0.75f}, {1, 1, 0, 0}, {1, 1, 1, 1}, {0, 0, 0, 0.5f}};
  for (int i = 0; i < 4; ++i)
    for (int q = 0; q < 4; ++q) EXPECT_FLOAT_EQ(c[i].density[q], expect[i][q]) << i << "," << q;
  EXPECT_FALSE(c[0].line_work);
}

TEST(ImageCells, AveragesFinerPixelsExactly) {
  // 16 × 2 px at 8 px/mm: each value covers 2 × 2 px (the track is the full 2 rows).
  std::vector<float> px(32, 1.0f);
  px[0] = 0;   // top-left pixel black: the first value is a quarter dark
  px[17] = 0;  // bottom row, column 1
  px[2] = 0.5f;
  const GrayImage img = image(16, 2, px);
  ImageCells cells(img, nullptr, screen(1, 4), 8);
  ASSERT_EQ(cells.cells(), 2u);
  const std::vector<CellValues> c = all(cells);
  EXPECT_FLOAT_EQ(c[0].density[0], 0.5f);   // two of its four pixels black
  EXPECT_FLOAT_EQ(c[0].density[1], 0.125f);  // one pixel half grey
  EXPECT_FLOAT_EQ(c[0].density[2], 0);
}

TEST(ImageCells, CoarsePixelsAreSplitByArea) {
  // 2 × 1 px at 1 px/mm, 2 cells/mm: each pixel spans two cells, each value an eighth of it.
  const GrayImage img = image(2, 1, {0, 1});
  ImageCells cells(img, nullptr, screen(2, 1), 1);
  ASSERT_EQ(cells.cells_per_track(), 4u);
  const std::vector<CellValues> c = all(cells);
  for (int q = 0; q < 4; ++q) {
    EXPECT_FLOAT_EQ(c[0].density[q], 1);
    EXPECT_FLOAT_EQ(c[3].density[q], 0);
  }
}

TEST(ImageCells, StaggeredTracksShiftHalfACellAndSeeWhiteBeyondTheEdge) {
  const GrayImage img = image(8, 2, std::vector<float>(16, 0.0f));  // all black
  ImageCells cells(img, nullptr, screen(1, 4, true), 4);
  const std::vector<CellValues> c = all(cells);
  ASSERT_EQ(c.size(), 4u);
  for (int q = 0; q < 4; ++q) EXPECT_FLOAT_EQ(c[1].density[q], 1);  // track 0, unshifted
  // Track 1, second cell: its second half lies beyond the image's right edge.
  EXPECT_FLOAT_EQ(c[3].density[0], 1);
  EXPECT_FLOAT_EQ(c[3].density[1], 1);
  EXPECT_FLOAT_EQ(c[3].density[2], 0);
  EXPECT_FLOAT_EQ(c[3].density[3], 0);
}

TEST(ImageCells, MaskMarksLineWorkAndMustMatchTheImage) {
  const GrayImage img = image(8, 1, std::vector<float>(8, 0.5f));
  const GrayImage mask = image(8, 1, {1, 1, 1, 1, 1, 1, 0, 1});
  ImageCells cells(img, &mask, screen(1, 4), 4);
  const std::vector<CellValues> c = all(cells);
  EXPECT_FALSE(c[0].line_work);
  EXPECT_TRUE(c[1].line_work);  // one of its values is line-work
  const GrayImage wrong = image(7, 1, std::vector<float>(7, 0));
  try {
    ImageCells bad(img, &wrong, screen(1, 4), 4);
    FAIL();
  } catch (const InputError& e) {
    EXPECT_STREQ(e.what(), "line-work mask is 7x1 pixels, the image 8x1: they must be the same size");
  }
}

TEST(ImageCells, RewindStartsOver) {
  const GrayImage img = image(8, 2, std::vector<float>(16, 0.25f));
  ImageCells cells(img, nullptr, screen(1, 4), 4);
  const std::vector<CellValues> a = all(cells);
  std::vector<CellValues> more(1);
  EXPECT_EQ(cells.next(more), 0u);
  cells.rewind();
  const std::vector<CellValues> b = all(cells);
  EXPECT_EQ(a.size(), b.size());
  EXPECT_FLOAT_EQ(b[0].density[0], 0.75f);
}

TEST(ImageCells, RefusesAResolutionOutOfRange) {
  const GrayImage img = image(8, 2, std::vector<float>(16, 0.25f));
  EXPECT_THROW(ImageCells(img, nullptr, screen(1, 4), 0), InputError);
  EXPECT_THROW(ImageCells(img, nullptr, screen(1000, 4), 4), InputError);
}

}  // namespace
}  // namespace mark

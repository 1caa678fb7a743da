// The material model: a single line marks as wide as the Gaussian-beam formula says at every
// speed (the reference width at the reference speed, nothing above the vanishing speed); pixel
// factors keep the marked share; a mark is half dark at the threshold; the grain has its rms;
// the view looks from above (top row = highest y) with the tones swapped for a dark part; the
// PNG carries its pixel size in pHYs.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>

#include "driver/sim/grey_png.hpp"
#include "driver/sim/part_image.hpp"
#include "tests/driver/png_info.hpp"

namespace mark {
namespace {

// A horizontal line along y = 0 from x = −1 to 1 mm at the given speed (dose = time).
DoseRaster line_dose(double speed_mm_s) {
  DoseRaster dose(0.005);
  dose.deposit_segment({-1, 0}, {1, 0}, 2.0 / speed_mm_s);
  return dose;
}

// Marked width across the line at x = 0, mm.
double marked_width(const DoseRaster& dose, const MarkResponse& r, int factor = 1) {
  const PartImage img = PartImage::render(dose, {-0.2, -0.2, 0.2, 0.2}, r, factor);
  const int i = static_cast<int>(std::lround((0 - img.x0_mm()) / img.pixel_mm()));
  double marked = 0;
  for (int j = 0; j < img.height(); ++j) marked += img.share(i, j);
  return marked * img.pixel_mm();
}

TEST(PartImage, SingleLineWidthFollowsTheBeamFormula) {
  const MarkResponse r;  // 40 µm beam; a 40 µm line at 1 m/s
  EXPECT_NEAR(r.line_width_mm(1000), 0.04, 1e-12);
  for (double v : {250.0, 500.0, 1000.0, 2000.0, 4000.0, 7000.0}) {
    SCOPED_TRACE(v);
    // The raster's 5 µm pixels resolve the edge to a pixel.
    EXPECT_NEAR(marked_width(line_dose(v), r), r.line_width_mm(v), 0.0051);
  }
  // A line as wide as the beam sits at e⁻² of its peak: it vanishes at e² times the speed.
  EXPECT_NEAR(r.vanishing_speed_mm_s(), 1000 * std::exp(2.0), 1e-6);
  EXPECT_EQ(r.line_width_mm(7500), 0.0);
  EXPECT_EQ(marked_width(line_dose(7500), r), 0.0);
}

TEST(PartImage, CoarsePixelsKeepTheMarkedShare) {
  const MarkResponse r;
  const DoseRaster d = line_dose(1000);
  EXPECT_NEAR(marked_width(d, r, 4), marked_width(d, r, 1), 1e-9);
}

TEST(PartImage, ViewLooksFromAboveAndSwapsToneForADarkPart) {
  DoseRaster dose(0.005);
  dose.deposit_segment({-1, 0.15}, {1, 0.15}, 0.002);  // a line near the top of the window
  PartLook look;
  look.grain_pct = 0;
  const PartImage light_part = PartImage::render(dose, {-0.2, -0.2, 0.2, 0.2}, MarkResponse{}, 1, look);
  const PartImage dark_part = PartImage::render(dose, {-0.2, -0.2, 0.2, 0.2}, MarkResponse{}, 1, dark_part_look(look));
  const GreyImage light = part_view(light_part, look), dark = part_view(dark_part, dark_part_look(look));
  const int row = static_cast<int>(std::lround(light.row_of(0.15)));
  // The line's middle is far above the threshold: fully dark on a light part, fully light on a
  // dark one; the bare part the other way round.
  const auto grey = [](double reflectance, const PartLook& l) {
    return std::lround(255 * reflectance / std::max(l.bare_reflectance, l.mark_reflectance));
  };
  EXPECT_EQ(light.at(10, row), grey(look.mark_reflectance, look));
  EXPECT_EQ(light.at(10, light.height - 1), grey(look.bare_reflectance, look));
  EXPECT_EQ(dark.at(10, row), 255);
  EXPECT_EQ(dark.at(10, light.height - 1), grey(look.mark_reflectance, look));
}

TEST(PartImage, AMarkIsHalfDarkWhereItsFluenceIsAtTheThreshold) {
  // A single line at the reference speed: its edge, half the reference width out, is at the
  // threshold, half dark; a tone ratio further in it is fully dark.
  const MarkResponse r;
  PartLook look;
  look.grain_pct = 0;
  const PartImage img = PartImage::render(line_dose(1000), {-0.2, -0.2, 0.2, 0.2}, r, 1, look);
  const int i = static_cast<int>(std::lround((0 - img.x0_mm()) / img.pixel_mm()));
  const int edge = static_cast<int>(std::lround((r.reference_width_mm / 2 - img.y0_mm()) / img.pixel_mm()));
  const double half = (look.bare_reflectance + look.mark_reflectance) / 2;
  // One raster pixel (5 µm) either side of the edge brackets the half-dark reflectance.
  EXPECT_LT(img.reflectance(i, edge - 1), half);
  EXPECT_GT(img.reflectance(i, edge + 1), half);
  EXPECT_NEAR(img.reflectance(i, static_cast<int>(std::lround(-img.y0_mm() / img.pixel_mm()))), look.mark_reflectance, 1e-6);
}

TEST(PartImage, GrainHasTheStatedRmsAndBelongsToThePart) {
  DoseRaster dose(0.005);
  PartLook look;  // 4 % grain
  const PartImage a = PartImage::render(dose, {-0.5, -0.5, 0.5, 0.5}, MarkResponse{}, 1, look);
  double sum = 0, sum2 = 0;
  for (int j = 0; j < a.height(); ++j)
    for (int i = 0; i < a.width(); ++i) sum += a.reflectance(i, j), sum2 += a.reflectance(i, j) * a.reflectance(i, j);
  const double n = a.width() * a.height(), mean = sum / n, rms = std::sqrt(sum2 / n - mean * mean);
  EXPECT_NEAR(mean, look.bare_reflectance, 0.002);
  EXPECT_NEAR(rms / mean, look.grain_pct / 100, 0.004);
  // Another window over the same spot of the part shows the same grain there.
  const PartImage b = PartImage::render(dose, {-0.3, -0.3, 0.7, 0.7}, MarkResponse{}, 1, look);
  EXPECT_FLOAT_EQ(a.reflectance(a.width() - 1, a.height() - 1),
                  b.reflectance(a.width() - 1 - 40, a.height() - 1 - 40));
}

TEST(DoseRaster, CopyRectMatchesPixelByPixel) {
  DoseRaster dose(0.005);
  dose.deposit_segment({-0.5, -0.3}, {0.7, 0.4}, 1.0);
  std::vector<float> out(300 * 200);
  ASSERT_TRUE(dose.copy_rect(-150, -90, 300, 200, out.data()));
  for (int y = 0; y < 200; ++y)
    for (int x = 0; x < 300; ++x) ASSERT_EQ(out[static_cast<std::size_t>(y * 300 + x)], dose.pixel(x - 150, y - 90));
  EXPECT_FALSE(dose.copy_rect(100000, 100000, 10, 10, out.data()));
}

TEST(GreyPng, CarriesThePixelSize) {
  GreyImage img;
  img.width = 40;
  img.height = 30;
  img.pixel_mm = 0.005;
  img.grey.assign(40 * 30, 200);
  const auto path = (std::filesystem::temp_directory_path() / "marker_grey_png_test.png").string();
  {
    const std::string bytes = encode_grey_png(img);
    std::ofstream(path, std::ios::binary).write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
  }
  const test::PngInfo info = test::read_png_info(path);
  ASSERT_TRUE(info.read);
  EXPECT_EQ(info.unit, PNG_RESOLUTION_METER);
  EXPECT_EQ(info.ppm_x, 200000u);  // 5 µm pixels: 200 000 per metre
  EXPECT_EQ(info.ppm_y, 200000u);
  EXPECT_EQ(info.width, 40);
  EXPECT_EQ(info.height, 30);
  std::filesystem::remove(path);
  img.pixel_mm = 0;
  EXPECT_THROW(encode_grey_png(img), std::runtime_error);
}

}  // namespace
}  // namespace mark

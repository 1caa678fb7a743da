// The simulated reader's camera against what optics and sensors are known to do: an edge
// blurred by the stated PSF (the error function of a Gaussian of σ = 0.42 λN on the sensor),
// shot and read noise of the stated size, a quadratic illumination falloff to the sensor's
// corner, the exposure TR 29158 calibrates to, the automatic pixel that fits the window to the
// sensor, seeded noise, and a window larger than the sensor cut to its field.
#include <gtest/gtest.h>

#include <cmath>

#include "driver/sim/camera_model.hpp"

namespace mark {
namespace {

// A half-plane dosed far above the threshold: x < 0 marked, x > 0 bare.
DoseRaster half_plane() {
  DoseRaster dose(0.005);
  for (double y = -1.2; y <= 1.2; y += 0.01) dose.deposit_segment({-1.2, y}, {-0.0, y}, 0.05);
  return dose;
}

CameraSettings quiet_camera() {
  CameraSettings s;
  s.look.grain_pct = 0;
  s.read_noise_grey = 0;
  s.full_well_ke = 1000;  // shot noise 0.1 grey: small against everything measured here
  s.falloff_pct = 0;
  return s;
}

TEST(CameraModel, AnEdgeIsBlurredByTheStatedPsf) {
  CameraSettings s = quiet_camera();
  s.pixel_um = 15;
  s.f_number = 16;  // σ = 0.42 · 0.625 µm · 16 / (3.75 / 15) = 16.8 µm on the part
  const double sigma_mm = camera_blur_mm(s, 0.015);
  EXPECT_NEAR(sigma_mm, 0.42 * 0.000625 * 16 / 0.25, 1e-12);
  const PartPhoto photo = photograph(half_plane(), {-0.6, -0.3, 0.6, 0.3}, MarkResponse{}, s);
  const GreyImage& p = photo.picture;
  const int row = p.height / 2;
  // The edge of the mark itself is where its fluence falls to the threshold, a little beyond
  // x = 0; measure where the profile crosses 10 % and 90 % of its swing.
  const double lo = p.at(2, row), hi = p.at(p.width - 3, row);
  const auto crossing = [&](double level) {
    for (int x = 1; x < p.width; ++x) {
      const double a = p.at(x - 1, row), b = p.at(x, row);
      if ((a - level) * (b - level) <= 0 && a != b) return (x - 1 + (level - a) / (b - a)) * p.pixel_mm;
    }
    return 0.0;
  };
  const double width_mm = crossing(lo + 0.9 * (hi - lo)) - crossing(lo + 0.1 * (hi - lo));
  // A Gaussian's 10–90 % rise is 2.563 σ; the pixel's width and the mark's own soft edge add
  // to it in quadrature (the box of one 15 µm pixel: σ = 15/√12 µm).
  const double box = 0.015 / std::sqrt(12.0);
  EXPECT_NEAR(width_mm, 2.563 * std::hypot(sigma_mm, box), 0.35 * 2.563 * sigma_mm);
  EXPECT_GT(width_mm, 2.563 * sigma_mm * 0.9);
}

TEST(CameraModel, ExposureAndNoiseAreAsStated) {
  CameraSettings s;
  s.look.grain_pct = 0;
  s.falloff_pct = 0;
  const PartPhoto photo = photograph(DoseRaster(0.005), {-1, -1, 1, 1}, MarkResponse{}, s);
  double sum = 0, sum2 = 0;
  for (std::uint8_t g : photo.picture.grey) sum += g, sum2 += double(g) * g;
  const double n = static_cast<double>(photo.picture.grey.size()), mean = sum / n;
  const double sd = std::sqrt(sum2 / n - mean * mean);
  // The bare surface is the lighter one: exposed to 78 % of full scale.
  EXPECT_NEAR(mean, 0.78 * 255, 0.3);
  // Shot noise of the mean's electrons and the read noise, both in grey levels; the rounding
  // to whole grey levels adds 1/12.
  const double electrons = mean / 255 * s.full_well_ke * 1000;
  const double expected = std::sqrt(electrons * std::pow(255 / (s.full_well_ke * 1000), 2) +
                                    s.read_noise_grey * s.read_noise_grey + 1.0 / 12);
  EXPECT_NEAR(sd, expected, 0.05 * expected);
}

TEST(CameraModel, NoiseIsSeeded) {
  CameraSettings s;
  const DoseRaster dose = half_plane();
  const FieldWindow w{-0.3, -0.3, 0.3, 0.3};
  const GreyImage a = photograph(dose, w, MarkResponse{}, s).picture;
  const GreyImage b = photograph(dose, w, MarkResponse{}, s).picture;
  s.seed = 2;
  const GreyImage c = photograph(dose, w, MarkResponse{}, s).picture;
  EXPECT_EQ(a.grey, b.grey);
  EXPECT_NE(a.grey, c.grey);
}

TEST(CameraModel, IlluminationFallsOffToTheSensorsCorners) {
  CameraSettings s = quiet_camera();
  s.falloff_pct = 20;
  s.pixel_um = 15;
  // A window as large as the sensor: its corner pixels are the sensor's.
  const double w = s.sensor_width_px * 0.015 / 2, h = s.sensor_height_px * 0.015 / 2;
  const GreyImage p = photograph(DoseRaster(0.005), {-w, -h, w - 0.015, h - 0.015}, MarkResponse{}, s).picture;
  ASSERT_EQ(p.width, s.sensor_width_px);
  ASSERT_EQ(p.height, s.sensor_height_px);
  const double centre = p.at(p.width / 2, p.height / 2), corner = p.at(0, 0);
  EXPECT_NEAR(corner / centre, 0.80, 0.01);
}

TEST(CameraModel, TheAutomaticPixelFitsTheWindowToTheSensor) {
  const CameraSettings s;
  // Small windows: the closest focus; large ones: the sensor's longer side spans them.
  EXPECT_NEAR(camera_pixel_mm(s, {0, 0, 4, 4}, 0.005), 0.015, 1e-12);
  EXPECT_NEAR(camera_pixel_mm(s, {0, 0, 40, 10}, 0.005), 0.035, 1e-12);  // 40/1280 = 31.25 µm → 35
  EXPECT_NEAR(camera_pixel_mm(s, {0, 0, 10, 40}, 0.005), 0.045, 1e-12);  // 40/960 = 41.7 µm → 45
  CameraSettings fixed;
  fixed.pixel_um = 12;
  EXPECT_NEAR(camera_pixel_mm(fixed, {0, 0, 40, 40}, 0.005), 0.015, 1e-12);  // a whole multiple of 5 µm
}

TEST(CameraModel, AWindowBeyondTheSensorIsCutToItsField) {
  CameraSettings s;
  s.pixel_um = 20;
  const GreyImage p = photograph(DoseRaster(0.005), {-20, -20, 20, 20}, MarkResponse{}, s).picture;
  EXPECT_EQ(p.width, s.sensor_width_px);
  EXPECT_EQ(p.height, s.sensor_height_px);
  EXPECT_NEAR(p.x0_mm + (p.width - 1) / 2.0 * p.pixel_mm, 0, p.pixel_mm);
}

TEST(CameraModel, SettingsOutsideTheirRangesAreRefused) {
  CameraSettings s;
  s.f_number = 0.1;
  EXPECT_THROW(check_camera_settings(s), std::invalid_argument);
  s = CameraSettings{};
  s.look.mark_reflectance = 0;
  EXPECT_THROW(check_camera_settings(s), std::invalid_argument);
}

}  // namespace
}  // namespace mark

#include "driver/sim/camera_model.hpp"
#include "driver/sim/param_range.hpp"

#include <algorithm>
#include <cmath>
#include <random>
#include <stdexcept>
#include <string>

namespace mark {
namespace {

void require(const char* what, double v, double lo, double hi) { require_param_range("camera", what, v, lo, hi); }

// A normalised Gaussian sampled at whole pixels out to 3σ.
std::vector<float> gaussian(double sigma_px) {
  const int reach = std::max(1, static_cast<int>(std::ceil(3 * sigma_px)));
  std::vector<float> k(2 * static_cast<std::size_t>(reach) + 1);
  double sum = 0;
  for (int i = -reach; i <= reach; ++i)
    sum += k[static_cast<std::size_t>(i + reach)] = static_cast<float>(std::exp(-0.5 * i * i / (sigma_px * sigma_px)));
  for (float& v : k) v = static_cast<float>(v / sum);
  return k;
}

// Separable blur with the edge pixels repeated (the part goes on beyond the window).
void blur(std::vector<float>& img, int w, int h, double sigma_px) {
  if (sigma_px < 0.05) return;
  const std::vector<float> k = gaussian(sigma_px);
  const int reach = static_cast<int>(k.size() / 2);
  std::vector<float> tmp(img.size());
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      float s = 0;
      for (int d = -reach; d <= reach; ++d)
        s += k[static_cast<std::size_t>(d + reach)] * img[static_cast<std::size_t>(y) * w + std::clamp(x + d, 0, w - 1)];
      tmp[static_cast<std::size_t>(y) * w + x] = s;
    }
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      float s = 0;
      for (int d = -reach; d <= reach; ++d)
        s += k[static_cast<std::size_t>(d + reach)] * tmp[static_cast<std::size_t>(std::clamp(y + d, 0, h - 1)) * w + x];
      img[static_cast<std::size_t>(y) * w + x] = s;
    }
}

}  // namespace

void check_camera_settings(const CameraSettings& s) {
  require("sensor width (px)", s.sensor_width_px, 64, 20000);
  require("sensor height (px)", s.sensor_height_px, 64, 20000);
  require("sensor pixel (µm)", s.sensor_pixel_um, 0.5, 50);
  if (s.pixel_um != 0) require("pixel on the part (µm)", s.pixel_um, 1, 1000);
  require("closest-focus pixel (µm)", s.min_pixel_um, 1, 1000);
  require("f-number", s.f_number, 0.7, 64);
  require("wavelength (nm)", s.wavelength_nm, 300, 1100);
  require("defocus (µm)", s.defocus_um, 0, 5000);
  require("illumination falloff (%)", s.falloff_pct, 0, 90);
  require("exposure (%)", s.exposure_pct, 10, 100);
  require("full well (ke)", s.full_well_ke, 0.1, 1000);
  require("read noise (grey)", s.read_noise_grey, 0, 50);
  check_part_look(s.look);
}

double camera_pixel_mm(const CameraSettings& s, const FieldWindow& w, double raster_mm) {
  double px = s.pixel_um / 1000;
  if (px <= 0)
    px = std::max({s.min_pixel_um / 1000, w.width() / s.sensor_width_px, w.height() / s.sensor_height_px});
  return std::max(1.0, std::ceil(px / raster_mm - 1e-9)) * raster_mm;
}

double camera_blur_mm(const CameraSettings& s, double pixel_mm) {
  const double magnification = s.sensor_pixel_um / (pixel_mm * 1000);
  const double diffraction_um = 0.42 * (s.wavelength_nm / 1000) * s.f_number / magnification;
  const double defocus_um = s.defocus_um / 4;  // a uniform disc of diameter D has σ = D/4
  return std::hypot(diffraction_um, defocus_um) / 1000;
}

GreyImage camera_picture(const PartImage& part, const CameraSettings& s) {
  check_camera_settings(s);
  const PartLook& look = s.look;  // the lighter of its two surfaces sets the exposure
  const int w = part.width(), h = part.height();
  std::vector<float> light(static_cast<std::size_t>(w) * h);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) light[static_cast<std::size_t>(y) * w + x] = part.reflectance(x, h - 1 - y);
  blur(light, w, h, camera_blur_mm(s, part.pixel_mm()) / part.pixel_mm());

  GreyImage img;
  img.width = w;
  img.height = h;
  img.pixel_mm = part.pixel_mm();
  img.x0_mm = part.x0_mm();
  img.top_mm = part.y0_mm() + (h - 1) * part.pixel_mm();
  img.grey.resize(light.size());
  const double gain = s.exposure_pct / 100 * 255 / std::max(look.bare_reflectance, look.mark_reflectance);
  // The reader is aimed at the middle of the window; its corners are the sensor's.
  const double cx = (w - 1) / 2.0, cy = (h - 1) / 2.0;
  const double corner2 = (s.sensor_width_px * s.sensor_width_px + s.sensor_height_px * s.sensor_height_px) / 4.0;
  const double grey_per_electron = 255 / (s.full_well_ke * 1000);
  std::mt19937 rng(s.seed);
  std::normal_distribution<double> normal(0, 1);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const double r2 = (x - cx) * (x - cx) + (y - cy) * (y - cy);
      const double illumination = std::max(0.0, 1 - s.falloff_pct / 100 * r2 / corner2);
      const double mean = light[static_cast<std::size_t>(y) * w + x] * illumination * gain;
      const double sigma = std::sqrt(std::max(0.0, mean) * grey_per_electron + s.read_noise_grey * s.read_noise_grey);
      img.grey[static_cast<std::size_t>(y) * w + x] =
          static_cast<std::uint8_t>(std::lround(std::clamp(mean + sigma * normal(rng), 0.0, 255.0)));
    }
  return img;
}

PartPhoto photograph(const DoseRaster& dose, const FieldWindow& window, const MarkResponse& response,
                     const CameraSettings& s, bool dark_part, double truth_pixel_mm) {
  check_camera_settings(s);
  const double px = camera_pixel_mm(s, window, dose.pixel_mm());
  // The camera sees its sensor's field at most: a window larger than that is cut to the sensor
  // about its middle, as the reader aimed there would see it.
  FieldWindow w = window;
  const double fov_w = s.sensor_width_px * px, fov_h = s.sensor_height_px * px;
  if (w.width() > fov_w) {
    const double c = (w.x0 + w.x1) / 2;
    w.x0 = c - fov_w / 2, w.x1 = c + fov_w / 2 - px;
  }
  if (w.height() > fov_h) {
    const double c = (w.y0 + w.y1) / 2;
    w.y0 = c - fov_h / 2, w.y1 = c + fov_h / 2 - px;
  }
  // Rendered once at the finer of the two pixels; the camera's is a whole number of those.
  const int factor = static_cast<int>(std::lround(px / dose.pixel_mm()));
  int fine = factor;
  while (fine > 1 && (fine * dose.pixel_mm() > truth_pixel_mm * (1 + 1e-9) || factor % fine)) --fine;
  const PartImage part = PartImage::render(dose, w, response, fine, dark_part ? dark_part_look(s.look) : s.look);
  return {camera_picture(part.binned(factor / fine), s), marked_share_view(part)};
}

}  // namespace mark

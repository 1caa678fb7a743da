#include "marker/head/lag_photo.hpp"

#include <algorithm>
#include <cmath>
#include <span>

namespace mark {

GreyImage photograph_lag_pattern(const SimScannerOptions& head, const LagPattern& pattern,
                                 CameraSettings camera) {
  SimScannerOptions o = head;
  o.record_lit_paths = false;
  o.probe = nullptr;
  SimScanner scanner(o);
  const std::vector<ScanSample> samples = lag_pattern_samples(pattern, o.tick_s);
  constexpr std::size_t kBlock = 100;
  for (std::size_t i = 0; i < samples.size(); i += kBlock)
    scanner.write(std::span<const ScanSample>(samples).subspan(i, std::min(kBlock, samples.size() - i)));
  return photograph_lag_dose(scanner.picture_dose(), pattern, camera);
}

GreyImage photograph_lag_dose(const DoseRaster& dose, const LagPattern& pattern, CameraSettings camera) {
  MarkResponse response;
  response.reference_speed_mm_s = pattern.fastest_mm_s();  // full power there marks one spot wide
  response.reference_width_mm = response.spot_diameter_mm;

  const Vec2 lo = pattern.min(), hi = pattern.max();
  const double margin = 1.5;
  const FieldWindow window{lo.x - margin, lo.y - margin, hi.x + margin, hi.y + margin};
  if (camera.pixel_um == 0) camera.pixel_um = kLagPhotoPixelUm;
  const double px = camera_pixel_mm(camera, window, dose.pixel_mm());
  camera.sensor_width_px = std::max(camera.sensor_width_px, static_cast<int>(std::ceil(window.width() / px)) + 1);
  camera.sensor_height_px = std::max(camera.sensor_height_px, static_cast<int>(std::ceil(window.height() / px)) + 1);
  return photograph(dose, window, response, camera, false, px).picture;
}

LagFit photographed_lag_fit(const SimScannerOptions& head) {
  const LagPattern pattern = lag_pattern(head.head);
  const GreyImage picture = photograph_lag_pattern(head, pattern);
  GrayImage grey{picture.width, picture.height, {}};
  grey.pixels.reserve(picture.grey.size());
  for (std::uint8_t v : picture.grey) grey.pixels.push_back(static_cast<float>(v) / 255.0f);
  return fit_lag_from_image(grey, picture.pixel_mm, pattern, "the simulated head's picture");
}

}  // namespace mark

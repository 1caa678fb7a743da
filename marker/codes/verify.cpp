#include "marker/codes/verify.hpp"

#include <algorithm>
#include <cmath>

#include "marker/codes/code_reader.hpp"
#include "marker/codes/synthetic_aperture.hpp"

namespace mark {
namespace {

constexpr int kSamplesPerSide = 8;  // points per module side where its marked share is sampled

// Share of the module's area (sampled on a grid, in the code's own frame) that is marked.
double module_share(const PlacedCode& code, const PartImage& part, int row, int col) {
  const Box b = code.module_box(row, col);
  double on = 0;
  for (int v = 0; v < kSamplesPerSide; ++v)
    for (int u = 0; u < kSamplesPerSide; ++u) {
      const Point local(b.min.x() + (u + 0.5) / kSamplesPerSide * b.width(),
                        b.min.y() + (v + 0.5) / kSamplesPerSide * b.height());
      const Point p = code.to_field * local;
      on += part.share_at(p.x(), p.y());
    }
  return on / (kSamplesPerSide * kSamplesPerSide);
}

}  // namespace

char axial_nonuniformity_grade(double pct) {
  return pct <= 6 ? 'A' : pct <= 8 ? 'B' : pct <= 10 ? 'C' : pct <= 12 ? 'D' : 'F';
}

CodeVerification verify_code(const PlacedCode& code, const CodeSpec& spec, const DoseRaster& dose,
                             const VerifyOptions& o) {
  CodeVerification v;
  v.expected_data = expected_decoded_data(spec);
  v.module_um = code.module_mm * 1000;
  // The symbol, its quiet zone and two modules of bare part around it, plus the beam's reach.
  const double margin = 2 * code.module_mm + o.response.spot_diameter_mm;
  const FieldWindow window{code.bounds.min.x() - margin, code.bounds.min.y() - margin,
                           code.bounds.max.x() + margin, code.bounds.max.y() + margin};
  // The camera's pixels: a whole number of raster pixels, about pixels_per_module per module.
  const int camera_factor =
      std::max(1, static_cast<int>(std::floor(code.module_mm / (o.pixels_per_module * dose.pixel_mm()))));
  const PartImage part = PartImage::render(dose, window, o.response, camera_factor);
  // An inverted code is for a dark part whose marks turn light: the camera sees that.
  v.image = camera_view(part, 1, code.layout.invert);
  v.camera_px_um = v.image.pixel_mm * 1000;

  const double aperture_px = o.aperture_modules * code.module_mm / v.image.pixel_mm;
  const ReadResult read = read_code(synthetic_aperture(v.image, aperture_px), spec.symbology,
                                    code.matrix.rows, code.matrix.cols);
  v.reader = read.reader;
  v.decoded = read.decoded;
  v.decoded_data = read.data;
  v.data_match = read.decoded && read.data == v.expected_data;
  if (read.decoded && read.module_x_px > 0) {
    v.module_x_um = read.module_x_px * v.camera_px_um;
    if (read.module_y_px > 0) {
      v.module_y_um = read.module_y_px * v.camera_px_um;
      const double mean = (*v.module_x_um + *v.module_y_um) / 2;
      v.axial_nonuniformity_pct = 100 * std::abs(*v.module_x_um - *v.module_y_um) / mean;
    }
  }

  // Against the intended grid: every module of the symbol, and for an inverted code the quiet
  // zone too (it is marked then).
  const bool linear = is_linear(code.matrix.symbology);
  const int q = code.layout.invert ? code.quiet_modules : 0;
  const int qr = linear ? 0 : q;
  double fill_sum = 0, spill_sum = 0;
  std::size_t fill_n = 0, spill_n = 0;
  v.fill_ratio_min = 1;
  for (int r = -qr; r < code.matrix.rows + qr; ++r)
    for (int c = -q; c < code.matrix.cols + q; ++c) {
      const bool inside = r >= 0 && r < code.matrix.rows && c >= 0 && c < code.matrix.cols;
      const bool to_mark = (inside && code.matrix.dark(r, c)) != code.layout.invert;
      const double share = module_share(code, part, r, c);
      if (to_mark) {
        fill_sum += share, ++fill_n;
        v.fill_ratio_min = std::min(v.fill_ratio_min, share);
        v.modules_wrong += share < 0.5;
      } else {
        spill_sum += share, ++spill_n;
        v.modules_wrong += share >= 0.5;
      }
    }
  v.fill_ratio = fill_n ? fill_sum / static_cast<double>(fill_n) : 0;
  if (!fill_n) v.fill_ratio_min = 0;
  v.spill_ratio = spill_n ? spill_sum / static_cast<double>(spill_n) : 0;
  return v;
}

}  // namespace mark

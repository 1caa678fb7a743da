#include "driver/sim/part_image.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace mark {
namespace {

// The Gaussian's 1-D factor sampled at whole raster pixels out to 2w (where it has fallen to
// e⁻⁸), normalised to unit mass per mm.
std::vector<float> kernel(double w_mm, double pixel_mm) {
  const int reach = std::max(1, static_cast<int>(std::ceil(2.0 * w_mm / pixel_mm)));
  std::vector<float> k(2 * static_cast<std::size_t>(reach) + 1);
  double sum = 0;
  for (int i = -reach; i <= reach; ++i) {
    const double x = i * pixel_mm;
    sum += k[static_cast<std::size_t>(i + reach)] = static_cast<float>(std::exp(-2 * x * x / (w_mm * w_mm)));
  }
  for (float& v : k) v = static_cast<float>(v / (sum * pixel_mm));
  return k;
}

// Raster rows per strip: memory stays a few megabytes however wide the window.
constexpr std::int64_t kStripRows = 256;

}  // namespace

PartImage PartImage::render(const DoseRaster& dose, const FieldWindow& w, const MarkResponse& response,
                            int factor, std::int64_t max_pixels) {
  if (factor < 1) throw std::invalid_argument("part image: pixel factor must be at least 1");
  if (!(w.x1 > w.x0 && w.y1 > w.y0)) throw std::invalid_argument("part image: empty window");
  PartImage img;
  const double p = dose.pixel_mm();
  img.pixel_mm_ = p * factor;
  const auto ix0 = static_cast<std::int64_t>(std::floor(w.x0 / p));
  const auto iy0 = static_cast<std::int64_t>(std::floor(w.y0 / p));
  const std::int64_t nx = static_cast<std::int64_t>(std::ceil((w.x1 - w.x0) / img.pixel_mm_)) + 1;
  const std::int64_t ny = static_cast<std::int64_t>(std::ceil((w.y1 - w.y0) / img.pixel_mm_)) + 1;
  if (nx * ny > max_pixels)
    throw std::invalid_argument("part image: " + std::to_string(nx) + "×" + std::to_string(ny) +
                                " pixels of " + std::to_string(img.pixel_mm_ * 1000) +
                                " µm exceed " + std::to_string(max_pixels));
  img.width_ = static_cast<int>(nx);
  img.height_ = static_cast<int>(ny);
  // Pixel (i, j) covers raster pixels ix0 + i·f … + f − 1: its centre is their middle.
  img.x0_ = (static_cast<double>(ix0) + 0.5 * (factor - 1)) * p;
  img.y0_ = (static_cast<double>(iy0) + 0.5 * (factor - 1)) * p;
  img.share_.assign(static_cast<std::size_t>(nx * ny), 0.0f);

  const float threshold = static_cast<float>(response.threshold_s_mm2());
  const std::vector<float> k = kernel(response.beam_radius_mm(), p);
  const std::int64_t reach = static_cast<std::int64_t>(k.size() / 2);
  const std::int64_t fine_w = nx * factor;               // raster columns the image covers
  const std::int64_t in_w = fine_w + 2 * reach;          // plus the beam's reach either side
  const std::int64_t strip = std::max<std::int64_t>(1, kStripRows / factor) * factor;
  std::vector<float> mass, rows, line(static_cast<std::size_t>(fine_w));
  std::vector<std::uint16_t> count(static_cast<std::size_t>(nx));
  for (std::int64_t r0 = 0; r0 < ny * factor; r0 += strip) {
    const std::int64_t r1 = std::min(ny * factor, r0 + strip);
    const std::int64_t in_h = (r1 - r0) + 2 * reach;
    mass.resize(static_cast<std::size_t>(in_w * in_h));
    if (!dose.copy_rect(ix0 - reach, iy0 + r0 - reach, in_w, in_h, mass.data())) continue;
    // Along x: each input row spread over the image's columns.
    rows.assign(static_cast<std::size_t>(fine_w * in_h), 0.0f);
    for (std::int64_t y = 0; y < in_h; ++y) {
      const float* in = &mass[static_cast<std::size_t>(y * in_w)];
      float* out = &rows[static_cast<std::size_t>(y * fine_w)];
      for (std::int64_t x = 0; x < in_w; ++x) {
        if (in[x] == 0) continue;
        for (std::int64_t d = -reach; d <= reach; ++d) {
          const std::int64_t o = x - reach + d;
          if (o >= 0 && o < fine_w) out[o] += in[x] * k[static_cast<std::size_t>(d + reach)];
        }
      }
    }
    // Along y, one output row at a time; threshold; count into the image's pixels.
    for (std::int64_t r = r0; r < r1; ++r) {
      std::fill(line.begin(), line.end(), 0.0f);
      const std::int64_t centre = r - r0 + reach;
      for (std::int64_t d = -reach; d <= reach; ++d) {
        const float kd = k[static_cast<std::size_t>(d + reach)];
        const float* in = &rows[static_cast<std::size_t>((centre + d) * fine_w)];
        for (std::int64_t x = 0; x < fine_w; ++x) line[static_cast<std::size_t>(x)] += in[x] * kd;
      }
      if ((r % factor) == 0) std::fill(count.begin(), count.end(), 0);
      for (std::int64_t x = 0; x < fine_w; ++x) count[static_cast<std::size_t>(x / factor)] += line[static_cast<std::size_t>(x)] >= threshold;
      if ((r % factor) == factor - 1) {
        float* out = &img.share_[static_cast<std::size_t>((r / factor) * nx)];
        for (std::int64_t i = 0; i < nx; ++i)
          out[i] = static_cast<float>(count[static_cast<std::size_t>(i)]) / static_cast<float>(factor * factor);
      }
    }
  }
  return img;
}

float PartImage::share_at(double x, double y) const {
  const auto i = static_cast<int>(std::lround((x - x0_) / pixel_mm_));
  const auto j = static_cast<int>(std::lround((y - y0_) / pixel_mm_));
  return i >= 0 && j >= 0 && i < width_ && j < height_ ? share_[index(i, j)] : 0.0f;
}

CameraImage camera_view(const PartImage& part, int factor, bool invert) {
  factor = std::max(1, factor);
  CameraImage cam;
  cam.width = (part.width() + factor - 1) / factor;
  cam.height = (part.height() + factor - 1) / factor;
  cam.pixel_mm = part.pixel_mm() * factor;
  cam.grey.resize(static_cast<std::size_t>(cam.width) * cam.height);
  const double bare = invert ? kMarkedGrey : kBareGrey, marked = invert ? kBareGrey : kMarkedGrey;
  for (int y = 0; y < cam.height; ++y)
    for (int x = 0; x < cam.width; ++x) {
      // Camera row y (top down) covers part rows from the top of the window.
      const int j_top = part.height() - 1 - y * factor;
      int n = 0;
      double on = 0;
      for (int b = 0; b < factor && j_top - b >= 0; ++b)
        for (int a = 0; a < factor && x * factor + a < part.width(); ++a)
          ++n, on += part.share(x * factor + a, j_top - b);
      const double share = n ? on / n : 0.0;
      cam.grey[static_cast<std::size_t>(y) * cam.width + x] =
          static_cast<std::uint8_t>(std::lround(bare + (marked - bare) * share));
    }
  return cam;
}

CameraImage part_picture(const DoseRaster& dose, const FieldWindow& w, const MarkResponse& response,
                         bool dark_part, int max_side_px) {
  const double side_px = std::max(w.x1 - w.x0, w.y1 - w.y0) / dose.pixel_mm() + 1;
  const int factor = std::max(1, static_cast<int>(std::ceil(side_px / std::max(16, max_side_px - 1))));
  return camera_view(PartImage::render(dose, w, response, factor), 1, dark_part);
}

bool dosed_window(const DoseRaster& dose, double margin_mm, FieldWindow& w) {
  std::int64_t ix0 = 0, iy0 = 0, ix1 = 0, iy1 = 0;
  if (!dose.bounds(ix0, iy0, ix1, iy1)) return false;
  const double p = dose.pixel_mm();
  w = {static_cast<double>(ix0) * p - margin_mm, static_cast<double>(iy0) * p - margin_mm,
       static_cast<double>(ix1) * p + margin_mm, static_cast<double>(iy1) * p + margin_mm};
  return true;
}

}  // namespace mark

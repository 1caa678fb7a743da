#include "driver/sim/part_image.hpp"
#include "driver/sim/param_range.hpp"

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

// A normally distributed number (unit variance, Irwin–Hall of four uniforms) fixed by the raster
// pixel and the seed: the surface's grain belongs to the part, not to the window looked at.
float grain_at(std::int64_t gx, std::int64_t gy, std::uint32_t seed) {
  std::uint64_t z = static_cast<std::uint64_t>(gx) * 0x9E3779B97F4A7C15ull ^
                    static_cast<std::uint64_t>(gy) * 0xC2B2AE3D27D4EB4Full ^ (std::uint64_t{seed} << 32);
  z ^= z >> 30, z *= 0xBF58476D1CE4E5B9ull, z ^= z >> 27, z *= 0x94D049BB133111EBull, z ^= z >> 31;
  float sum = 0;
  for (int k = 0; k < 4; ++k) sum += static_cast<float>((z >> (16 * k)) & 0xFFFF) / 65536.0f;
  return (sum - 2.0f) * 1.7320508f;
}

void require_look(const char* what, double v, double lo, double hi) {
  require_param_range("part look", what, v, lo, hi);
}

}  // namespace

void check_part_look(const PartLook& l) {
  require_look("bare reflectance", l.bare_reflectance, 0.001, 1);
  require_look("mark reflectance", l.mark_reflectance, 0.001, 1);
  require_look("tone ratio", l.tone_ratio, 1.01, 1000);
  require_look("grain (%)", l.grain_pct, 0, 50);
}

PartLook dark_part_look(PartLook look) {
  std::swap(look.bare_reflectance, look.mark_reflectance);
  return look;
}

PartImage PartImage::render(const DoseRaster& dose, const FieldWindow& w, const MarkResponse& response,
                            int factor, const PartLook& look, std::int64_t max_pixels) {
  if (factor < 1) throw std::invalid_argument("part image: pixel factor must be at least 1");
  if (!(w.x1 > w.x0 && w.y1 > w.y0)) throw std::invalid_argument("part image: empty window");
  check_part_look(look);
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
  img.reflectance_.assign(static_cast<std::size_t>(nx * ny), 0.0f);

  const float threshold = static_cast<float>(response.threshold_s_mm2());
  // Darkness d = ½ + ½·ln(F/F_th)/ln(tone), clamped to 0..1: nothing below F_th/tone.
  const float faint = threshold / static_cast<float>(look.tone_ratio);
  const float inv_log_tone = static_cast<float>(0.5 / std::log(look.tone_ratio));
  const float bare = static_cast<float>(look.bare_reflectance), dark = static_cast<float>(look.mark_reflectance);
  const float grain = static_cast<float>(look.grain_pct / 100);
  const std::vector<float> k = kernel(response.beam_radius_mm(), p);
  const std::int64_t reach = static_cast<std::int64_t>(k.size() / 2);
  const std::int64_t fine_w = nx * factor;               // raster columns the image covers
  const std::int64_t in_w = fine_w + 2 * reach;          // plus the beam's reach either side
  const std::int64_t strip = std::max<std::int64_t>(1, kStripRows / factor) * factor;
  std::vector<float> mass, rows, line(static_cast<std::size_t>(fine_w));
  std::vector<std::uint16_t> count(static_cast<std::size_t>(nx));
  std::vector<float> light(static_cast<std::size_t>(nx));
  const float per_pixel = 1.0f / static_cast<float>(factor * factor);
  for (std::int64_t r0 = 0; r0 < ny * factor; r0 += strip) {
    const std::int64_t r1 = std::min(ny * factor, r0 + strip);
    const std::int64_t in_h = (r1 - r0) + 2 * reach;
    mass.resize(static_cast<std::size_t>(in_w * in_h));
    const bool dosed = dose.copy_rect(ix0 - reach, iy0 + r0 - reach, in_w, in_h, mass.data());
    if (dosed) {
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
    }
    // Along y, one output row at a time; threshold and darkness; count into the image's pixels.
    for (std::int64_t r = r0; r < r1; ++r) {
      std::fill(line.begin(), line.end(), 0.0f);
      if (dosed) {
        const std::int64_t centre = r - r0 + reach;
        for (std::int64_t d = -reach; d <= reach; ++d) {
          const float kd = k[static_cast<std::size_t>(d + reach)];
          const float* in = &rows[static_cast<std::size_t>((centre + d) * fine_w)];
          for (std::int64_t x = 0; x < fine_w; ++x) line[static_cast<std::size_t>(x)] += in[x] * kd;
        }
      }
      if ((r % factor) == 0) {
        std::fill(count.begin(), count.end(), 0);
        std::fill(light.begin(), light.end(), 0.0f);
      }
      const std::int64_t gy = iy0 + r;
      for (std::int64_t x = 0; x < fine_w; ++x) {
        const float f = line[static_cast<std::size_t>(x)];
        float d = 0;
        if (f > faint) d = std::clamp(0.5f + inv_log_tone * std::log(f / threshold), 0.0f, 1.0f);
        const float refl = (bare + (dark - bare) * d) * (1.0f + grain * grain_at(ix0 + x, gy, look.seed));
        const auto i = static_cast<std::size_t>(x / factor);
        count[i] += f >= threshold;
        light[i] += std::max(0.0f, refl);
      }
      if ((r % factor) == factor - 1) {
        const std::size_t row = static_cast<std::size_t>((r / factor) * nx);
        for (std::int64_t i = 0; i < nx; ++i) {
          img.share_[row + i] = static_cast<float>(count[static_cast<std::size_t>(i)]) * per_pixel;
          img.reflectance_[row + i] = light[static_cast<std::size_t>(i)] * per_pixel;
        }
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

PartImage PartImage::binned(int k) const {
  if (k <= 1) return *this;
  PartImage out;
  out.pixel_mm_ = pixel_mm_ * k;
  out.width_ = (width_ + k - 1) / k;
  out.height_ = (height_ + k - 1) / k;
  // Coarse pixel (i, j) covers fine pixels i·k … i·k + k − 1: its centre is their middle.
  out.x0_ = x0_ + 0.5 * (k - 1) * pixel_mm_;
  out.y0_ = y0_ + 0.5 * (k - 1) * pixel_mm_;
  out.share_.assign(static_cast<std::size_t>(out.width_) * out.height_, 0.0f);
  out.reflectance_.assign(out.share_.size(), 0.0f);
  for (int j = 0; j < out.height_; ++j)
    for (int i = 0; i < out.width_; ++i) {
      float share = 0, light = 0;
      int n = 0;
      for (int b = 0; b < k && j * k + b < height_; ++b)
        for (int a = 0; a < k && i * k + a < width_; ++a, ++n) {
          share += share_[index(i * k + a, j * k + b)];
          light += reflectance_[index(i * k + a, j * k + b)];
        }
      out.share_[out.index(i, j)] = share / static_cast<float>(n);
      out.reflectance_[out.index(i, j)] = light / static_cast<float>(n);
    }
  return out;
}

namespace {

// An empty picture of the part's window, row 0 at the top.
GreyImage blank_view(const PartImage& part) {
  GreyImage img;
  img.width = part.width();
  img.height = part.height();
  img.pixel_mm = part.pixel_mm();
  img.x0_mm = part.x0_mm();
  img.top_mm = part.y0_mm() + (part.height() - 1) * part.pixel_mm();
  img.grey.resize(static_cast<std::size_t>(img.width) * img.height);
  return img;
}

}  // namespace

GreyImage part_view(const PartImage& part, const PartLook& look) {
  GreyImage img = blank_view(part);
  const double scale = 255 / std::max(look.bare_reflectance, look.mark_reflectance);
  for (int y = 0; y < img.height; ++y)
    for (int x = 0; x < img.width; ++x)
      img.grey[static_cast<std::size_t>(y) * img.width + x] = static_cast<std::uint8_t>(
          std::lround(std::clamp(part.reflectance(x, part.height() - 1 - y) * scale, 0.0, 255.0)));
  return img;
}

GreyImage marked_share_view(const PartImage& part) {
  GreyImage img = blank_view(part);
  for (int y = 0; y < img.height; ++y)
    for (int x = 0; x < img.width; ++x)
      img.grey[static_cast<std::size_t>(y) * img.width + x] =
          static_cast<std::uint8_t>(std::lround(255 * part.share(x, part.height() - 1 - y)));
  return img;
}

GreyImage part_picture(const DoseRaster& dose, const FieldWindow& w, const MarkResponse& response,
                       const PartLook& look, int max_side_px) {
  const double side_px = std::max(w.x1 - w.x0, w.y1 - w.y0) / dose.pixel_mm() + 1;
  const int factor = std::max(1, static_cast<int>(std::ceil(side_px / std::max(16, max_side_px - 1))));
  return part_view(PartImage::render(dose, w, response, factor, look), look);
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

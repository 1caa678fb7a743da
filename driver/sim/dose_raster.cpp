#include "driver/sim/dose_raster.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace mark {

DoseRaster::DoseRaster(double pixel_mm) : pixel_mm_(pixel_mm) {
  if (!(pixel_mm > 0)) throw std::invalid_argument("dose raster pixel must be positive");
}

std::uint64_t DoseRaster::key(std::int64_t tx, std::int64_t ty) {
  return (static_cast<std::uint64_t>(static_cast<std::uint32_t>(tx)) << 32) |
         static_cast<std::uint32_t>(ty);
}

float* DoseRaster::pixel_ref(std::int64_t ix, std::int64_t iy) {
  const std::int64_t tx = ix >> tile_bits, ty = iy >> tile_bits;  // floor for negatives too
  const std::uint64_t k = key(tx, ty);
  // The key of tile (−1, −1) is all ones, so the cache needs its own "empty" state.
  if (!cached_tile_ || k != cached_key_) {
    auto& slot = tiles_[k];
    if (!slot) slot = std::make_unique<Tile>();
    cached_key_ = k;
    cached_tile_ = slot.get();
  }
  return &cached_tile_->dose[static_cast<std::size_t>(((iy & (tile_size - 1)) << tile_bits) |
                                                      (ix & (tile_size - 1)))];
}

const float* DoseRaster::find_pixel(std::int64_t ix, std::int64_t iy) const {
  const auto it = tiles_.find(key(ix >> tile_bits, iy >> tile_bits));
  if (it == tiles_.end()) return nullptr;
  return &it->second->dose[static_cast<std::size_t>(((iy & (tile_size - 1)) << tile_bits) |
                                                    (ix & (tile_size - 1)))];
}

void DoseRaster::deposit(Vec2 p, double dose) {
  const double fx = p.x / pixel_mm_, fy = p.y / pixel_mm_;
  const double x0 = std::floor(fx), y0 = std::floor(fy);
  const double wx = fx - x0, wy = fy - y0;
  const auto ix = static_cast<std::int64_t>(x0), iy = static_cast<std::int64_t>(y0);
  *pixel_ref(ix, iy) += static_cast<float>(dose * (1 - wx) * (1 - wy));
  *pixel_ref(ix + 1, iy) += static_cast<float>(dose * wx * (1 - wy));
  *pixel_ref(ix, iy + 1) += static_cast<float>(dose * (1 - wx) * wy);
  *pixel_ref(ix + 1, iy + 1) += static_cast<float>(dose * wx * wy);
  total_ += dose;
}

void DoseRaster::deposit_segment(Vec2 a, Vec2 b, double dose) {
  const double len = norm(b - a);
  const int n = std::max(1, static_cast<int>(std::ceil(len / (0.5 * pixel_mm_))));
  const double share = dose / n;
  for (int i = 0; i < n; ++i) deposit(a + ((i + 0.5) / n) * (b - a), share);
}

void DoseRaster::add(const DoseRaster& other) {
  if (other.pixel_mm_ != pixel_mm_) throw std::invalid_argument("dose rasters of different pixel sizes cannot be added");
  for (const auto& [k, tile] : other.tiles_) {
    auto& slot = tiles_[k];
    if (!slot) slot = std::make_unique<Tile>();
    for (std::size_t i = 0; i < slot->dose.size(); ++i) slot->dose[i] += tile->dose[i];
  }
  total_ += other.total_;
}

void DoseRaster::reserve_along(const std::vector<Vec2>& polyline, double margin_mm) {
  const double tile_mm = tile_size * pixel_mm_;
  // Points along the polyline are at most half a tile apart; a square of half-width
  // margin + half a tile around each covers everything within margin of the segments between.
  const double reach = margin_mm + 0.5 * tile_mm;
  const auto reserve_square = [&](Vec2 p) {
    const auto tx0 = static_cast<std::int64_t>(std::floor((p.x - reach) / tile_mm));
    const auto tx1 = static_cast<std::int64_t>(std::floor((p.x + reach) / tile_mm));
    const auto ty0 = static_cast<std::int64_t>(std::floor((p.y - reach) / tile_mm));
    const auto ty1 = static_cast<std::int64_t>(std::floor((p.y + reach) / tile_mm));
    for (std::int64_t ty = ty0; ty <= ty1; ++ty)
      for (std::int64_t tx = tx0; tx <= tx1; ++tx) {
        auto& slot = tiles_[key(tx, ty)];
        if (!slot) slot = std::make_unique<Tile>();
      }
  };
  for (std::size_t i = 0; i < polyline.size(); ++i) {
    const Vec2 a = polyline[i], b = i + 1 < polyline.size() ? polyline[i + 1] : a;
    const int n = std::max(1, static_cast<int>(std::ceil(norm(b - a) / (0.5 * tile_mm))));
    for (int k = 0; k <= n; ++k) reserve_square(a + (static_cast<double>(k) / n) * (b - a));
  }
  cached_tile_ = nullptr;
}

double DoseRaster::pixel(std::int64_t ix, std::int64_t iy) const {
  const float* p = find_pixel(ix, iy);
  return p ? *p : 0.0;
}

double DoseRaster::sum_disc(Vec2 p, double radius_mm) const {
  // Anti-aliased disc: a pixel counts fully inside r − ½ px, partly (linearly) out to r + ½ px,
  // so the window holds the same area wherever p falls between pixel centres — a hard-edged
  // disc of 3 px radius would swing by 7/6 as p moves half a pixel along a line.
  const double r = radius_mm / pixel_mm_;
  const double cx = p.x / pixel_mm_, cy = p.y / pixel_mm_;
  const double reach = r + 0.5;
  const double inner2 = r > 0.5 ? (r - 0.5) * (r - 0.5) : 0.0;
  std::uint64_t last_key = 0;
  bool looked_up = false;  // no key value can mean "none": tile (−1, −1) is all ones
  const Tile* last_tile = nullptr;
  const auto iy0 = static_cast<std::int64_t>(std::ceil(cy - reach));
  const auto iy1 = static_cast<std::int64_t>(std::floor(cy + reach));
  double sum = 0;
  for (std::int64_t iy = iy0; iy <= iy1; ++iy) {
    const double dy = static_cast<double>(iy) - cy;
    const double half = std::sqrt(std::max(0.0, reach * reach - dy * dy));
    const auto ix0 = static_cast<std::int64_t>(std::ceil(cx - half));
    const auto ix1 = static_cast<std::int64_t>(std::floor(cx + half));
    // One tile lookup per run of the row inside a tile, remembered across rows (sum_disc runs
    // in quality loops; a disc rarely spans more than two tiles).
    for (std::int64_t ix = ix0; ix <= ix1;) {
      const std::int64_t run_end = std::min(ix1, (ix | (tile_size - 1)));
      const std::uint64_t k = key(ix >> tile_bits, iy >> tile_bits);
      if (!looked_up || k != last_key) {
        const auto it = tiles_.find(k);
        last_tile = it == tiles_.end() ? nullptr : it->second.get();
        last_key = k;
        looked_up = true;
      }
      if (last_tile) {
        const float* row = &last_tile->dose[static_cast<std::size_t>(
            ((iy & (tile_size - 1)) << tile_bits) | (ix & (tile_size - 1)))];
        for (std::int64_t k = 0; k <= run_end - ix; ++k) {
          const double dx = static_cast<double>(ix + k) - cx;
          const double d2 = dx * dx + dy * dy;
          // Inside r − ½ the weight is 1; only the one-pixel rim needs the square root.
          sum += d2 <= inner2 ? row[k] : std::clamp(reach - std::sqrt(d2), 0.0, 1.0) * row[k];
        }
      }
      ix = run_end + 1;
    }
  }
  return sum;
}

bool DoseRaster::bounds(std::int64_t& ix0, std::int64_t& iy0, std::int64_t& ix1,
                        std::int64_t& iy1) const {
  if (tiles_.empty()) return false;
  ix0 = iy0 = INT64_MAX;
  ix1 = iy1 = INT64_MIN;
  for (const auto& [k, tile] : tiles_) {
    const auto tx = static_cast<std::int32_t>(static_cast<std::uint32_t>(k >> 32));
    const auto ty = static_cast<std::int32_t>(static_cast<std::uint32_t>(k & 0xffffffffu));
    ix0 = std::min<std::int64_t>(ix0, std::int64_t{tx} * tile_size);
    iy0 = std::min<std::int64_t>(iy0, std::int64_t{ty} * tile_size);
    ix1 = std::max<std::int64_t>(ix1, std::int64_t{tx} * tile_size + tile_size - 1);
    iy1 = std::max<std::int64_t>(iy1, std::int64_t{ty} * tile_size + tile_size - 1);
  }
  return true;
}

double DoseRaster::max_pixel() const {
  float m = 0;
  for (const auto& [k, tile] : tiles_)
    for (float d : tile->dose) m = std::max(m, d);
  return m;
}

bool DoseRaster::copy_rect(std::int64_t ix0, std::int64_t iy0, std::int64_t w, std::int64_t h,
                           float* out) const {
  std::fill(out, out + w * h, 0.0f);
  bool any = false;
  for (std::int64_t ty = iy0 >> tile_bits; ty <= (iy0 + h - 1) >> tile_bits; ++ty)
    for (std::int64_t tx = ix0 >> tile_bits; tx <= (ix0 + w - 1) >> tile_bits; ++tx) {
      const auto it = tiles_.find(key(tx, ty));
      if (it == tiles_.end()) continue;
      any = true;
      const std::int64_t x0 = std::max(ix0, tx * tile_size), x1 = std::min(ix0 + w, (tx + 1) * tile_size);
      const std::int64_t y0 = std::max(iy0, ty * tile_size), y1 = std::min(iy0 + h, (ty + 1) * tile_size);
      for (std::int64_t y = y0; y < y1; ++y) {
        const float* src = &it->second->dose[static_cast<std::size_t>(((y - ty * tile_size) << tile_bits) +
                                                                     (x0 - tx * tile_size))];
        std::copy(src, src + (x1 - x0), out + (y - iy0) * w + (x0 - ix0));
      }
    }
  return any;
}

}  // namespace mark

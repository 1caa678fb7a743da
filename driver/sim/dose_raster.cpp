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

std::unique_ptr<DoseRaster::Tile> DoseRaster::new_tile() {
  if (spare_.empty()) return std::make_unique<Tile>();
  std::unique_ptr<Tile> t = std::move(spare_.back());
  spare_.pop_back();
  t->stale = true;
  return t;
}

void DoseRaster::freshen(Tile& t) {
  if (!t.stale) return;
  std::fill(t.dose.begin(), t.dose.end(), 0.0f);
  t.stale = false;
}

void DoseRaster::clear() {
  for (auto& [k, tile] : tiles_)
    if (spare_.size() < kSpareTiles) spare_.push_back(std::move(tile));
  tiles_.clear();
  total_ = 0;
  cached_tile_ = nullptr;
}

float* DoseRaster::pixel_ref(std::int64_t ix, std::int64_t iy) {
  const std::int64_t tx = ix >> tile_bits, ty = iy >> tile_bits;  // floor for negatives too
  const std::uint64_t k = key(tx, ty);
  // The key of tile (−1, −1) is all ones, so the cache needs its own "empty" state.
  if (!cached_tile_ || k != cached_key_) {
    auto& slot = tiles_[k];
    if (!slot) slot = new_tile();
    freshen(*slot);
    cached_key_ = k;
    cached_tile_ = slot.get();
  }
  return &cached_tile_->dose[static_cast<std::size_t>(((iy & (tile_size - 1)) << tile_bits) |
                                                      (ix & (tile_size - 1)))];
}

const float* DoseRaster::find_pixel(std::int64_t ix, std::int64_t iy) const {
  const auto it = tiles_.find(key(ix >> tile_bits, iy >> tile_bits));
  if (it == tiles_.end() || it->second->stale) return nullptr;
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
    if (tile->stale) continue;
    auto& slot = tiles_[k];
    if (!slot) slot = new_tile();
    freshen(*slot);
    for (std::size_t i = 0; i < slot->dose.size(); ++i) slot->dose[i] += tile->dose[i];
  }
  total_ += other.total_;
}

void DoseRaster::reserve_along(const std::vector<std::vector<Vec2>>& polylines, double margin_mm) {
  const double tile_mm = tile_size * pixel_mm_;
  // Points along each polyline are at most half a tile apart; a square of half-width
  // margin + half a tile around each covers everything within margin of the segments between.
  const double reach = margin_mm + 0.5 * tile_mm;
  // The squares are marked in a bitmap of the tiles over the paths' bounding box first, and each
  // wanted tile looked up once: a square per point straight into the hash map cost 58 ms on the
  // cps job (62 characters, a 1 mm margin), a lookup for every tile of every square.
  double x0 = INFINITY, y0 = INFINITY, x1 = -INFINITY, y1 = -INFINITY;
  for (const auto& line : polylines)
    for (const Vec2& p : line) {
      x0 = std::min(x0, p.x), y0 = std::min(y0, p.y);
      x1 = std::max(x1, p.x), y1 = std::max(y1, p.y);
    }
  if (!(x0 <= x1 && y0 <= y1)) return;  // no points
  if (!(std::max({-x0, -y0, x1, y1}) < 1e6))  // a km off, or not a number: no head's field
    throw std::invalid_argument("dose raster: a lit path lies outside ±1000 m");
  const auto tile_of = [&](double v) { return static_cast<std::int64_t>(std::floor(v / tile_mm)); };
  const std::int64_t tx0 = tile_of(x0 - reach), ty0 = tile_of(y0 - reach);
  const std::int64_t w = tile_of(x1 + reach) - tx0 + 1, h = tile_of(y1 + reach) - ty0 + 1;
  // Up to 4096 tiles across (a 1.3 m field at 5 µm pixels; 16 MB of bitmap); wider, each
  // square goes to the map directly.
  const bool dense = w <= 4096 && h <= 4096;
  std::vector<unsigned char> wanted(dense ? static_cast<std::size_t>(w * h) : 0, 0);
  const auto want_square = [&](Vec2 p) {
    const std::int64_t ax = tile_of(p.x - reach) - tx0, bx = tile_of(p.x + reach) - tx0;
    const std::int64_t ay = tile_of(p.y - reach) - ty0, by = tile_of(p.y + reach) - ty0;
    for (std::int64_t ty = ay; ty <= by; ++ty) {
      if (dense) {
        std::fill_n(wanted.begin() + ty * w + ax, bx - ax + 1, 1);
        continue;
      }
      for (std::int64_t tx = ax; tx <= bx; ++tx) {
        auto& slot = tiles_[key(tx0 + tx, ty0 + ty)];
        if (!slot) slot = new_tile();
      }
    }
  };
  for (const auto& line : polylines)
    for (std::size_t i = 0; i < line.size(); ++i) {
      const Vec2 a = line[i], b = i + 1 < line.size() ? line[i + 1] : a;
      const int n = std::max(1, static_cast<int>(std::ceil(norm(b - a) / (0.5 * tile_mm))));
      for (int k = 0; k < n; ++k) want_square(a + (static_cast<double>(k) / n) * (b - a));
      if (i + 1 == line.size()) want_square(a);
    }
  for (std::int64_t ty = 0; dense && ty < h; ++ty)
    for (std::int64_t tx = 0; tx < w; ++tx)
      if (wanted[static_cast<std::size_t>(ty * w + tx)]) {
        auto& slot = tiles_[key(tx0 + tx, ty0 + ty)];
        if (!slot) slot = new_tile();
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
        last_tile = it == tiles_.end() || it->second->stale ? nullptr : it->second.get();
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
    if (!tile->stale)
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
      if (it->second->stale) continue;  // zeros
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

#include "driver/sim/dose_raster.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace mark {

DoseRaster::DoseRaster(double pixel_mm, std::size_t dense_tiles)
    : pixel_mm_(pixel_mm), dense_budget_(dense_tiles) {
  if (!(pixel_mm > 0)) throw std::invalid_argument("dose raster pixel must be positive");
  // Four: a deposit touches up to four tiles, and none it just wrote may be packed under it.
  if (dense_tiles < 4) throw std::invalid_argument("dose raster: at least 4 dense tiles");
}

std::uint64_t DoseRaster::key(std::int64_t tx, std::int64_t ty) {
  return (static_cast<std::uint64_t>(static_cast<std::uint32_t>(tx)) << 32) |
         static_cast<std::uint32_t>(ty);
}

void DoseRaster::give_floats(Tile& t, std::uint64_t k) {
  // Over budget, the tile the beam left longest ago is packed first; its floats become this one's.
  while (dense_count_ >= dense_budget_ && !lru_.empty()) {
    const std::uint64_t old = lru_.back();
    pack(old, *tiles_.at(old));
  }
  if (spare_.empty()) {
    t.dose.assign(tile_size * tile_size, 0.0f);
    t.stale = false;
  } else {
    t.dose = std::move(spare_.back());
    spare_.pop_back();
    t.stale = true;
  }
  lru_.push_front(k);
  t.lru = lru_.begin();
  ++dense_count_;
}

void DoseRaster::pack(std::uint64_t k, Tile& t) {
  if (!t.stale) {
    auto packed = std::make_unique<PackedTile>(t.dose);
    if (!packed->values().empty()) {
      packed_bytes_ += packed->bytes();
      t.packed = std::move(packed);
    }
  }
  if (spare_.size() < kSpareTiles) spare_.push_back(std::move(t.dose));
  t.dose = {};
  t.stale = false;
  lru_.erase(t.lru);
  --dense_count_;
  if (cached_tile_ && cached_key_ == k) cached_tile_ = nullptr;
}

DoseRaster::Tile& DoseRaster::dense_tile(std::uint64_t k) {
  auto& slot = tiles_[k];
  if (!slot) slot = std::make_unique<Tile>();
  Tile& t = *slot;
  if (t.dense()) {
    lru_.splice(lru_.begin(), lru_, t.lru);
  } else {
    give_floats(t, k);
    if (t.packed) {
      t.packed->unpack(t.dose);
      t.stale = false;
      packed_bytes_ -= t.packed->bytes();
      t.packed.reset();
    }
  }
  freshen(t);
  return t;
}

void DoseRaster::freshen(Tile& t) {
  if (!t.stale) return;
  std::fill(t.dose.begin(), t.dose.end(), 0.0f);
  t.stale = false;
}

void DoseRaster::clear() {
  for (auto& [k, tile] : tiles_)
    if (tile->dense() && spare_.size() < kSpareTiles) spare_.push_back(std::move(tile->dose));
  tiles_.clear();
  lru_.clear();
  dense_count_ = 0;
  packed_bytes_ = 0;
  total_ = 0;
  cached_tile_ = nullptr;
}

std::size_t DoseRaster::memory_bytes() const {
  constexpr std::size_t floats = tile_size * tile_size * sizeof(float);
  return (dense_count_ + spare_.size()) * floats + packed_bytes_ + tiles_.size() * sizeof(Tile);
}

float* DoseRaster::pixel_ref(std::int64_t ix, std::int64_t iy) {
  const std::int64_t tx = ix >> tile_bits, ty = iy >> tile_bits;  // floor for negatives too
  const std::uint64_t k = key(tx, ty);
  // The key of tile (−1, −1) is all ones, so the cache needs its own "empty" state.
  if (!cached_tile_ || k != cached_key_) {
    cached_tile_ = &dense_tile(k);
    cached_key_ = k;
  }
  return &cached_tile_->dose[static_cast<std::size_t>(((iy & (tile_size - 1)) << tile_bits) |
                                                      (ix & (tile_size - 1)))];
}

const DoseRaster::Tile* DoseRaster::find_tile(std::uint64_t k) const {
  const auto it = tiles_.find(k);
  if (it == tiles_.end()) return nullptr;
  const Tile& t = *it->second;
  if (t.dense() ? t.stale : !t.packed) return nullptr;
  return &t;
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
  cached_tile_ = nullptr;
  for (const auto& [k, tile] : other.tiles_) {
    const Tile* from = other.find_tile(k);
    if (!from) continue;
    std::vector<float>& to = dense_tile(k).dose;
    if (from->dense()) {
      for (std::size_t i = 0; i < to.size(); ++i) to[i] += from->dose[i];
    } else {
      for (int r = 0; r < tile_size; ++r)
        from->packed->for_each_in_row(r, 0, tile_size - 1, [&](int c, float v) { to[static_cast<std::size_t>(r * tile_size + c)] += v; });
    }
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
  // Within the budget every wanted tile gets its floats now; beyond it, only its place (the
  // deposits will pack the tiles the beam has left), and the spares are filled to the budget.
  std::vector<std::uint64_t> wanted_keys;
  const auto want_tile = [&](std::int64_t tx, std::int64_t ty) {
    if (!tiles_.contains(key(tx, ty))) wanted_keys.push_back(key(tx, ty));
  };
  const auto want_square = [&](Vec2 p) {
    const std::int64_t ax = tile_of(p.x - reach) - tx0, bx = tile_of(p.x + reach) - tx0;
    const std::int64_t ay = tile_of(p.y - reach) - ty0, by = tile_of(p.y + reach) - ty0;
    for (std::int64_t ty = ay; ty <= by; ++ty) {
      if (dense) {
        std::fill_n(wanted.begin() + ty * w + ax, bx - ax + 1, 1);
        continue;
      }
      for (std::int64_t tx = ax; tx <= bx; ++tx) want_tile(tx0 + tx, ty0 + ty);
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
      if (wanted[static_cast<std::size_t>(ty * w + tx)]) want_tile(tx0 + tx, ty0 + ty);
  std::sort(wanted_keys.begin(), wanted_keys.end());  // the sparse path may name a tile twice
  wanted_keys.erase(std::unique(wanted_keys.begin(), wanted_keys.end()), wanted_keys.end());
  const bool fits = dense_count_ + wanted_keys.size() <= dense_budget_;
  for (const std::uint64_t k : wanted_keys) {
    auto& slot = tiles_[k];
    slot = std::make_unique<Tile>();
    if (fits) give_floats(*slot, k);
  }
  const std::size_t room = std::min(dense_budget_ - std::min(dense_count_, dense_budget_), kSpareTiles);
  while (!fits && spare_.size() < room) spare_.emplace_back(tile_size * tile_size, 0.0f);
  cached_tile_ = nullptr;
}

double DoseRaster::pixel(std::int64_t ix, std::int64_t iy) const {
  const Tile* t = find_tile(key(ix >> tile_bits, iy >> tile_bits));
  if (!t) return 0.0;
  const int col = static_cast<int>(ix & (tile_size - 1)), row = static_cast<int>(iy & (tile_size - 1));
  return t->dense() ? t->dose[static_cast<std::size_t>((row << tile_bits) | col)] : t->packed->value(col, row);
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
        last_tile = find_tile(k);
        last_key = k;
        looked_up = true;
      }
      // Inside r − ½ the weight is 1; only the one-pixel rim needs the square root.
      const auto weighted = [&](std::int64_t x, double v) {
        const double dx = static_cast<double>(x) - cx;
        const double d2 = dx * dx + dy * dy;
        return d2 <= inner2 ? v : std::clamp(reach - std::sqrt(d2), 0.0, 1.0) * v;
      };
      if (last_tile && last_tile->dense()) {
        const float* row = &last_tile->dose[static_cast<std::size_t>(
            ((iy & (tile_size - 1)) << tile_bits) | (ix & (tile_size - 1)))];
        for (std::int64_t k = 0; k <= run_end - ix; ++k) sum += weighted(ix + k, row[k]);
      } else if (last_tile) {
        const std::int64_t base = ix & ~std::int64_t{tile_size - 1};
        last_tile->packed->for_each_in_row(static_cast<int>(iy & (tile_size - 1)), static_cast<int>(ix - base),
                                           static_cast<int>(run_end - base),
                                           [&](int c, float v) { sum += weighted(base + c, v); });
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
  for (const auto& [k, tile] : tiles_) {
    if (!find_tile(k)) continue;
    for (float d : tile->dense() ? tile->dose : tile->packed->values()) m = std::max(m, d);
  }
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
      const Tile* t = find_tile(key(tx, ty));
      if (!t) continue;  // zeros
      const std::int64_t x0 = std::max(ix0, tx * tile_size), x1 = std::min(ix0 + w, (tx + 1) * tile_size);
      const std::int64_t y0 = std::max(iy0, ty * tile_size), y1 = std::min(iy0 + h, (ty + 1) * tile_size);
      for (std::int64_t y = y0; y < y1; ++y) {
        float* to = out + (y - iy0) * w;
        const int row = static_cast<int>(y - ty * tile_size);
        if (t->dense()) {
          const float* src = &t->dose[static_cast<std::size_t>((row << tile_bits) + (x0 - tx * tile_size))];
          std::copy(src, src + (x1 - x0), to + (x0 - ix0));
        } else {
          t->packed->for_each_in_row(row, static_cast<int>(x0 - tx * tile_size),
                                     static_cast<int>(x1 - 1 - tx * tile_size),
                                     [&](int c, float v) { to[tx * tile_size + c - ix0] = v; });
        }
      }
    }
  return any;
}

}  // namespace mark

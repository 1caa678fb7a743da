#pragma once
// Laser dose on the work piece: seconds at full power per pixel (default 5 µm pixels), stored in
// lazily allocated square tiles so only the area the beam touched costs memory (a whole 110 mm
// field at 5 µm would be 484 M pixels).
#include <cstdint>
#include <memory>
#include <unordered_map>
#include <vector>

#include "driver/vec2.hpp"

namespace mark {

class DoseRaster {
 public:
  explicit DoseRaster(double pixel_mm = 0.005);

  // Deposit `dose` at point p, split bilinearly over the four nearest pixel centres.
  void deposit(Vec2 p, double dose);
  // Deposit `dose` spread evenly along the segment a→b (points ≤ half a pixel apart), so a fast
  // move leaves a continuous trace rather than dots.
  void deposit_segment(Vec2 a, Vec2 b, double dose);
  // Adds every pixel of `other` (same pixel size, else std::invalid_argument): the dose of a
  // production part whose objects the scanner marked as separate jobs, each clearing its own.
  void add(const DoseRaster& other);

  // Allocate every tile within margin_mm of the polylines now, so later deposits there do not
  // allocate (the simulator sizes its raster before the first sample of a job).
  void reserve_along(const std::vector<std::vector<Vec2>>& polylines, double margin_mm);
  std::size_t tiles() const { return tiles_.size(); }
  // Empties the raster for the next job and keeps up to kSpareTiles of its tiles for reuse: the
  // next job's reserve_along then zeroes memory it already owns instead of asking for fresh pages
  // (a station's trigger waits for it before the first sample).
  void clear();
  static constexpr std::size_t kSpareTiles = 4096;  // 64 MiB of 64 × 64 floats

  // Dose of pixel (ix, iy); pixel (ix, iy) is centred on (ix·pixel, iy·pixel) mm.
  double pixel(std::int64_t ix, std::int64_t iy) const;
  // Dose in a spot-sized disc of radius_mm around p: pixels weighted by how far inside the disc
  // their centres lie (anti-aliased edge one pixel wide), so the sum does not jump with p.
  double sum_disc(Vec2 p, double radius_mm) const;
  double total() const { return total_; }
  double pixel_mm() const { return pixel_mm_; }
  bool empty() const { return tiles_.empty(); }

  // Pixel-index bounds of every allocated tile (inclusive); false when empty.
  bool bounds(std::int64_t& ix0, std::int64_t& iy0, std::int64_t& ix1, std::int64_t& iy1) const;
  // Highest pixel value.
  double max_pixel() const;
  // Copies pixels [ix0, ix0 + w) × [iy0, iy0 + h) row by row (row iy0 first) into `out`
  // (w × h values, zeros where nothing was deposited), a tile at a time. Returns whether any
  // tile overlapped the rectangle.
  bool copy_rect(std::int64_t ix0, std::int64_t iy0, std::int64_t w, std::int64_t h, float* out) const;

  static constexpr int tile_bits = 6;  // 64 × 64 pixel tiles
  static constexpr int tile_size = 1 << tile_bits;

 private:
  struct Tile {
    std::vector<float> dose = std::vector<float>(tile_size * tile_size, 0.0f);
    // Still holds an earlier job's values (a spare reserved again): reads as zero, and is zeroed
    // on its first deposit. Most reserved tiles lie in the margin and are never deposited in, so
    // the job's start does not wait to zero them.
    bool stale = false;
  };
  static std::uint64_t key(std::int64_t tx, std::int64_t ty);
  std::unique_ptr<Tile> new_tile();  // from the spares (stale) when there are any, else a fresh zeroed one
  static void freshen(Tile& t);      // zeroes a stale tile before its first deposit
  float* pixel_ref(std::int64_t ix, std::int64_t iy);           // allocates
  const float* find_pixel(std::int64_t ix, std::int64_t iy) const;  // nullptr if absent

  double pixel_mm_;
  double total_ = 0;
  std::unordered_map<std::uint64_t, std::unique_ptr<Tile>> tiles_;
  std::vector<std::unique_ptr<Tile>> spare_;  // tiles of earlier jobs (clear()), not zeroed
  // one-tile cache: consecutive deposits almost always hit the same tile
  std::uint64_t cached_key_ = 0;  // meaningful only while cached_tile_ is set
  Tile* cached_tile_ = nullptr;
};

}  // namespace mark

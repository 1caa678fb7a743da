#pragma once
// Laser dose on the work piece: seconds at full power per pixel (default 5 µm pixels), stored in
// lazily allocated square tiles so only the area the beam touched costs memory (a whole 110 mm
// field at 5 µm would be 484 M pixels). Memory stays bounded as the marked area grows: at most
// a budget of tiles are kept as plain floats (the ones the beam used last); the beam's older
// tiles are packed without their zeros (PackedTile, exact), and unpacked if it comes back.
#include <cstdint>
#include <list>
#include <memory>
#include <unordered_map>
#include <vector>

#include "driver/sim/packed_tile.hpp"
#include "driver/vec2.hpp"

namespace mark {

class DoseRaster {
 public:
  // dense_tiles: how many tiles may be plain floats at once (at least 4). Within it nothing is
  // ever packed, so a job of up to 64 MiB of tiles costs what it did before packing existed.
  explicit DoseRaster(double pixel_mm = 0.005, std::size_t dense_tiles = kDenseTiles);
  static constexpr std::size_t kDenseTiles = 4096;  // 64 MiB of 64 × 64 floats

  // Deposit `dose` at point p, split bilinearly over the four nearest pixel centres.
  void deposit(Vec2 p, double dose);
  // Deposit `dose` spread evenly along the segment a→b (points ≤ half a pixel apart), so a fast
  // move leaves a continuous trace rather than dots.
  void deposit_segment(Vec2 a, Vec2 b, double dose);
  // Adds every pixel of `other` (same pixel size, else std::invalid_argument): the dose of a
  // production part whose objects the scanner marked as separate jobs, each clearing its own.
  void add(const DoseRaster& other);

  // Allocate every tile within margin_mm of the polylines now, so later deposits there do not
  // allocate (the simulator sizes its raster before the first sample of a job). When they are
  // more than the dense budget, each gets its place but no floats, and the spare floats are
  // filled to the budget: deposits then allocate only the packed copy of the tile they push out.
  void reserve_along(const std::vector<std::vector<Vec2>>& polylines, double margin_mm);
  std::size_t tiles() const { return tiles_.size(); }
  std::size_t dense_tiles() const { return dense_count_; }
  // Bytes the raster holds now: dense tiles, packed tiles and spares.
  std::size_t memory_bytes() const;
  // Empties the raster for the next job and keeps up to kSpareTiles of its tiles for reuse: the
  // next job's reserve_along then zeroes memory it already owns instead of asking for fresh pages
  // (a station's trigger waits for it before the first sample).
  void clear();
  static constexpr std::size_t kSpareTiles = kDenseTiles;

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
  static_assert(tile_size == PackedTile::kSide);

 private:
  struct Tile {
    // Dense: tile_size² floats. Empty while packed (or never deposited in, packed == nullptr).
    std::vector<float> dose;
    std::unique_ptr<PackedTile> packed;
    // Still holds an earlier job's values (spare floats reserved again): reads as zero, and is
    // zeroed on its first deposit. Most reserved tiles lie in the margin and are never deposited
    // in, so the job's start does not wait to zero them.
    bool stale = false;
    std::list<std::uint64_t>::iterator lru;  // its place in lru_ while dense
    bool dense() const { return !dose.empty(); }
  };
  static std::uint64_t key(std::int64_t tx, std::int64_t ty);
  // The tile at key k as plain floats, made (or unpacked) if need be, first in lru_.
  Tile& dense_tile(std::uint64_t k);
  void give_floats(Tile& t, std::uint64_t k);  // spare floats (stale) or fresh zeroed ones; into lru_
  void pack(std::uint64_t k, Tile& t);          // to PackedTile; its floats go to the spares
  static void freshen(Tile& t);                 // zeroes a stale tile before its first deposit
  float* pixel_ref(std::int64_t ix, std::int64_t iy);  // allocates
  const Tile* find_tile(std::uint64_t k) const;       // nullptr if absent or reading as zero

  double pixel_mm_;
  std::size_t dense_budget_;
  double total_ = 0;
  std::unordered_map<std::uint64_t, std::unique_ptr<Tile>> tiles_;
  std::list<std::uint64_t> lru_;  // dense tiles, the one deposited in last first
  std::size_t dense_count_ = 0;
  std::size_t packed_bytes_ = 0;
  std::vector<std::vector<float>> spare_;  // floats of earlier tiles, not zeroed
  // one-tile cache: consecutive deposits almost always hit the same tile
  std::uint64_t cached_key_ = 0;  // meaningful only while cached_tile_ is set
  Tile* cached_tile_ = nullptr;
};

}  // namespace mark

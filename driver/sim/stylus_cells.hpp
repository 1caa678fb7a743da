#pragma once
// Cells measured from a cut-depth profile: the depth the diamond left at each stylus sample
// along the track (µm, 0 where it did not cut), split into cells by the cell clock and measured
// as a gravure press would see them — deepest point, length of the opening along the track,
// area of the opening on the surface and engraved volume (the ink a cell carries).
//
// The stylus is a diamond with two faces meeting at the stylus angle θ (≈ 120°, US 5,825,503),
// so a cut of depth c is 2·c·tan(θ/2) wide at the surface and its cross-section holds
// c²·tan(θ/2). Each sample stands for the slot of track between its neighbours' midpoints; where
// the cut starts or ends inside a slot, the crossing is placed by linear interpolation, so
// lengths resolve far below one sample pitch.
//
// The cell clock: cell j is made of the samples n with ⌊n·f_cell / f_s⌋ = j (f_s the stylus
// rate), exactly, for any whole-hertz cell rate — 32 samples a cell at 6.25 kHz, 62 or 63 at
// 3.2 kHz.
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

namespace mark {

struct CellGeometry {
  std::uint32_t cell_rate_hz = 6250;  // cells engraved per second
  double cell_pitch_um = 100;         // cell length along the track
  double stylus_angle_deg = 120;      // included angle of the diamond
};

// Throws std::invalid_argument when the geometry is impossible (rate 0 or above half the
// stylus rate, pitch not positive, angle outside 10° .. 170°).
void validate(const CellGeometry& geometry);

struct CellFigures {
  float depth_um = 0;    // deepest cut in the cell
  float length_um = 0;   // cut length along the track
  float area_um2 = 0;    // area of the opening on the cylinder surface
  float volume_um3 = 0;  // engraved volume
};

// First stylus sample of cell j.
std::uint64_t first_sample_of_cell(std::uint64_t cell, std::uint32_t cell_rate_hz);
// The cell a stylus sample belongs to.
std::uint64_t cell_of_sample(std::uint64_t sample, std::uint32_t cell_rate_hz);

// Streaming measurement: add() the cut depth of every sample in order, then finish(). Figures
// go into a vector whose capacity is fixed by the constructor (reserve enough: cells beyond it
// are counted in dropped_cells(), never allocated — the meter runs on the drain thread).
class CellMeter {
 public:
  CellMeter(const CellGeometry& geometry, std::size_t max_cells);

  void add(float cut_um);
  // Measures the last sample and closes the last (partial) cell.
  void finish();
  void clear();  // back to sample 0, keeping the capacity

  const std::vector<CellFigures>& cells() const { return cells_; }
  std::uint64_t dropped_cells() const { return dropped_; }

 private:
  void measure(float left, float here, float right);  // the sample `here`, between neighbours
  void close_cell();

  CellGeometry geometry_;
  double slot_um_;       // track length per sample
  double half_width_;    // tan(θ/2)
  std::size_t max_cells_;
  std::vector<CellFigures> cells_;
  CellFigures current_;
  std::uint64_t cell_ = 0;        // cell of the sample being measured
  std::uint64_t next_first_ = 0;  // first sample of cell_ + 1
  std::uint64_t sample_ = 0;      // index of the sample being measured
  std::uint64_t seen_ = 0;        // samples added
  float prev_ = 0, cur_ = 0;
  std::uint64_t dropped_ = 0;
};

// Every cell of a whole profile (tests, the intended toolpath).
std::vector<CellFigures> measure_cells(std::span<const float> cut_um, const CellGeometry& geometry);

}  // namespace mark

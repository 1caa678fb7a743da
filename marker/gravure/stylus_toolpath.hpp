#pragma once
// The stylus toolpath (the seed's toolpath 64/65), synchronised to the cylinder: cells from a
// CellSource become control points (control_points.hpp), the control points a monotone cubic
// (monotone_curve.hpp: it never leaves the depths of the two knots around it), and the curve is
// sampled at the stylus clock.
//
// Synchronisation (FIG. 6): the cylinder turns at a fixed cell rate, so stylus sample n stands
// for track position x_n = n · f_cell / f_s cells — cell ⌊x_n⌋, at the fraction x_n − ⌊x_n⌋ of it
// (driver/sim/stylus_cells.hpp keeps the exact integer form). At 6.25 kHz that is the seed's 32
// samples a cell; any whole-hertz rate works. The stream is the cells of every track back to
// back (helical engraving: one track follows the next without a pause), starting and ending
// with the stylus lifted above the surface.
//
// `advance_samples` shifts the toolpath earlier by the latency of filters and head (sample n
// carries the toolpath at n + advance), so the stylus reaches each depth when the cylinder
// brings the cell under it.
#include <cstdint>
#include <span>
#include <vector>

#include "marker/gravure/cell_setup.hpp"
#include "marker/gravure/cell_source.hpp"
#include "marker/gravure/monotone_curve.hpp"
#include "marker/gravure/drive_source.hpp"

namespace mark {

struct ToolpathOptions {
  GravureSetup setup;
  std::uint32_t cell_rate_hz = 6250;
  double advance_samples = 0;
};

struct CellCounts {
  std::uint64_t white = 0, single = 0, channel = 0, split = 0;
  std::uint64_t line_work = 0;  // cells cut with the LW setup
};

struct CellPosition {
  std::uint64_t cell = 0;
  double fraction = 0;  // 0 .. 1 within the cell
};
// Where on the track stylus sample n is, for a cell rate in whole hertz.
CellPosition cell_position(std::uint64_t sample, std::uint32_t cell_rate_hz);

class StylusToolpath : public DriveSource {
 public:
  // The source is read from its current position (rewind it first to restart a job).
  StylusToolpath(CellSource& cells, const ToolpathOptions& options);

  std::uint64_t cells() const { return cells_; }
  std::uint64_t total_samples() const override { return total_samples_; }
  std::uint64_t samples_done() const { return next_sample_; }

  // The next toolpath depths (µm below the surface) in stylus-clock order; returns how many
  // were written, 0 once every sample has been given.
  std::size_t next(std::span<double> out) override;

  // Kinds of the cells planned so far (all of them once the stream has ended).
  const CellCounts& counts() const { return counts_; }

 private:
  void feed();  // plans the next cells and appends their control points to the curve
  void add_knot(double x, double depth);

  CellSource& source_;
  ToolpathOptions options_;
  std::uint64_t cells_;
  std::uint64_t total_samples_;
  std::uint64_t next_sample_ = 0;
  std::uint64_t cells_planned_ = 0;
  double x_per_sample_;
  MonotoneCurve curve_;
  MonotoneCurve::Segment segment_;  // the piece the next sample falls in
  std::vector<CellValues> batch_;
  bool pending_ = false;  // a knot held back so a coincident one can merge with it
  double pending_x_ = 0, pending_depth_ = 0;
  CellCounts counts_;
};

}  // namespace mark

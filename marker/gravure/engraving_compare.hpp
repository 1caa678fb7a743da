#pragma once
// How far the engraving is from what was intended, two ways:
//
// - against the cells the image asked for (issue 23): each cell's depth from its grey levels and
//   the setup's full-cell scaler, independent of the control points and of the curve through
//   them — a toolpath that overshoots between knots shows here and nowhere else;
// - against the toolpath's own curve: the cut-depth profile the head left against the toolpath
//   (its positive part: the toolpath above the surface cuts nothing), sample by sample along the
//   track, and cell by cell (depth, length, volume) — how well the filters make the head follow
//   the curve, whatever the curve is.
#include <span>
#include <vector>

#include "driver/sim/stylus_cells.hpp"
#include "marker/gravure/cell_source.hpp"
#include "marker/gravure/stylus_toolpath.hpp"

namespace mark {

struct DepthError {
  double rms_um = 0;
  double max_um = 0;
};

// Over the common length of the two profiles (the engraved one may carry the drain's safe
// samples at the end: no cut).
DepthError depth_error(std::span<const float> engraved_um, std::span<const float> intended_um);

struct CellError {
  double depth_rms_um = 0;
  double length_rms_um = 0;
  double volume_rms_pct = 0;  // rms volume error over the mean intended volume of engraved cells
};
CellError cell_error(std::span<const CellFigures> engraved, std::span<const CellFigures> intended);

// The depth each cell was asked for, µm, in stream order: the full-cell scaler of its total
// density D = mean of its four values (CT or LW setup as flagged); of the denser pair's for a
// cell cut as two sub-cells (FIG. 4); 0 for a white cell (D < 1 %), which is held above the
// surface — or, where deeper, the channel a dark neighbour enters or leaves by on the common
// boundary (claims 11–12: channel scaler of its first / last value), which the stylus must cut
// at the edge of this cell too. Rewinds the source before and after.
std::vector<float> intended_cell_depths(CellSource& cells, const GravureSetup& setup);

// Cell by cell: the deepest cut the head left in each cell against the depth it was asked for
// (over the common length; the engraved list may stop early on a cancelled job).
DepthError cell_depth_error(std::span<const CellFigures> engraved, std::span<const float> intended_um);

// The intended cut of a job: the toolpath without advance, its positive part, one value a
// sample. Rewinds the source before and after.
std::vector<float> intended_cut(CellSource& cells, ToolpathOptions options);

}  // namespace mark

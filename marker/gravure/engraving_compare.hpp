#pragma once
// How far the engraving is from what was intended: the cut-depth profile the head left against
// the toolpath's own (its positive part: the toolpath above the surface cuts nothing), sample by
// sample along the track, and cell by cell (depth, length, volume).
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

// The intended cut of a job: the toolpath without advance, its positive part, one value a
// sample. Rewinds the source before and after.
std::vector<float> intended_cut(CellSource& cells, ToolpathOptions options);

}  // namespace mark

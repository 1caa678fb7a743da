#include "marker/gravure/screen.hpp"

#include "marker/gravure/parameter_range.hpp"

namespace mark {

void validate(const GravureScreen& s) {
  check_range("screen cells per mm along the track", s.cells_per_mm_along, kCellsPerMmRange);
  check_range("screen cells per mm across the track", s.cells_per_mm_across, kCellsPerMmRange);
  check_range("cell rate", s.cell_rate_hz, kCellRateRange);
}

}  // namespace mark

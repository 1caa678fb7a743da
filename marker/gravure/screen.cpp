#include "marker/gravure/screen.hpp"

#include "marker/limits/gravure_settings.hpp"

namespace mark {

void validate(const GravureScreen& s) {
  check_range("screen cells per mm along the track", s.cells_per_mm_along, kCellsPerMmBounds.range());
  check_range("screen cells per mm across the track", s.cells_per_mm_across, kCellsPerMmBounds.range());
  check_range("cell rate", s.cell_rate_hz, kCellRateBounds.range());
}

}  // namespace mark

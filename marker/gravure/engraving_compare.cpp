#include "marker/gravure/engraving_compare.hpp"

#include <algorithm>
#include <cmath>

namespace mark {

DepthError depth_error(std::span<const float> engraved, std::span<const float> intended) {
  const std::size_t n = std::min(engraved.size(), intended.size());
  DepthError e;
  double sum = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const double d = static_cast<double>(engraved[i]) - intended[i];
    sum += d * d;
    e.max_um = std::max(e.max_um, std::abs(d));
  }
  e.rms_um = n ? std::sqrt(sum / static_cast<double>(n)) : 0;
  return e;
}

CellError cell_error(std::span<const CellFigures> engraved, std::span<const CellFigures> intended) {
  const std::size_t n = std::min(engraved.size(), intended.size());
  CellError e;
  if (n == 0) return e;
  double depth = 0, length = 0, volume = 0, mean_volume = 0;
  std::size_t engraved_cells = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const double dd = engraved[i].depth_um - intended[i].depth_um;
    const double dl = engraved[i].length_um - intended[i].length_um;
    const double dv = engraved[i].volume_um3 - intended[i].volume_um3;
    depth += dd * dd;
    length += dl * dl;
    volume += dv * dv;
    if (intended[i].volume_um3 > 0) {
      mean_volume += intended[i].volume_um3;
      ++engraved_cells;
    }
  }
  const double count = static_cast<double>(n);
  e.depth_rms_um = std::sqrt(depth / count);
  e.length_rms_um = std::sqrt(length / count);
  if (engraved_cells) e.volume_rms_pct = 100 * std::sqrt(volume / count) / (mean_volume / engraved_cells);
  return e;
}

std::vector<float> intended_cut(CellSource& cells, ToolpathOptions options) {
  cells.rewind();
  options.advance_samples = 0;
  StylusToolpath toolpath(cells, options);
  std::vector<float> cut;
  cut.reserve(toolpath.total_samples());
  std::vector<double> block(4096);
  while (const std::size_t n = toolpath.next(block))
    for (std::size_t i = 0; i < n; ++i) cut.push_back(static_cast<float>(std::max(0.0, block[i])));
  cells.rewind();
  return cut;
}

}  // namespace mark

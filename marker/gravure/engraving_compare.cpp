#include "marker/gravure/engraving_compare.hpp"

#include <algorithm>
#include <cmath>

#include "marker/gravure/control_points.hpp"

namespace mark {
namespace {

// rms and largest |difference(i)| over i < n.
template <class Difference>
DepthError error_over(std::size_t n, Difference difference) {
  DepthError e;
  double sum = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const double d = difference(i);
    sum += d * d;
    e.max_um = std::max(e.max_um, std::abs(d));
  }
  e.rms_um = n ? std::sqrt(sum / static_cast<double>(n)) : 0;
  return e;
}

}  // namespace

DepthError depth_error(std::span<const float> engraved, std::span<const float> intended) {
  return error_over(std::min(engraved.size(), intended.size()),
                    [&](std::size_t i) { return static_cast<double>(engraved[i]) - intended[i]; });
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

std::vector<float> intended_cell_depths(CellSource& cells, const GravureSetup& setup) {
  cells.rewind();
  // Per cell: the centre depth, and the channel depths at its start and end boundaries (0 for
  // a cell that starts and ends on the surface).
  std::vector<float> centre, entry, exit;
  std::vector<CellValues> batch(1024);
  while (const std::size_t n = cells.next(batch))
    for (std::size_t i = 0; i < n; ++i) {
      const CellValues& c = batch[i];
      const CellSetup& s = c.line_work ? setup.lw : setup.ct;
      const auto& d = c.density;
      // The kind (white / split / one cell / channel) is the control point generator's
      // decision; the depths are taken from the densities and the scalers, not its points.
      double deepest = 0, in = 0, out = 0;
      switch (plan_cell(c, setup).kind) {
        case CellKind::white: break;
        case CellKind::single: deepest = s.full_cell_depth((d[0] + d[1] + d[2] + d[3]) / 4.0); break;
        case CellKind::channel:
          deepest = s.full_cell_depth((d[0] + d[1] + d[2] + d[3]) / 4.0);
          in = s.channel_depth(d[0]);
          out = s.channel_depth(d[3]);
          break;
        case CellKind::split:
          deepest = s.full_cell_depth(std::max(d[0] + d[1], d[2] + d[3]) / 2.0);
          in = s.channel_depth(d[0]);
          out = s.channel_depth(d[3]);
          break;
      }
      centre.push_back(static_cast<float>(std::max(0.0, deepest)));
      entry.push_back(static_cast<float>(std::max(0.0, in)));
      exit.push_back(static_cast<float>(std::max(0.0, out)));
    }
  cells.rewind();
  // A cell's stylus also cuts its neighbours' channels where they meet it: the channel the
  // next cell enters by (reached at this cell's last sample) and the one the previous cell
  // left by (this cell's first sample lies on their common boundary).
  std::vector<float> depths(centre.size());
  for (std::size_t i = 0; i < centre.size(); ++i) {
    float d = centre[i];
    if (i > 0) d = std::max(d, exit[i - 1]);
    if (i + 1 < centre.size()) d = std::max(d, entry[i + 1]);
    depths[i] = d;
  }
  return depths;
}

DepthError cell_depth_error(std::span<const CellFigures> engraved, std::span<const float> intended) {
  return error_over(std::min(engraved.size(), intended.size()),
                    [&](std::size_t i) { return static_cast<double>(engraved[i].depth_um) - intended[i]; });
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

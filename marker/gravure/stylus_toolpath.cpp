#include "marker/gravure/stylus_toolpath.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "driver/sim/stylus_cells.hpp"
#include "driver/sim/stylus_head_model.hpp"
#include "marker/limits/gravure_settings.hpp"

namespace mark {
namespace {

// Control points closer than this (cell units) are one point: where a cell's exit and the next
// cell's entry both sit on their common boundary.
constexpr double kMergeGap = 1e-3;
constexpr std::size_t kBatch = 64;

}  // namespace

CellPosition cell_position(std::uint64_t sample, std::uint32_t rate) {
  const auto fs = static_cast<std::uint64_t>(kStylusRate_hz);
  const std::uint64_t scaled = sample * rate;
  return {scaled / fs, static_cast<double>(scaled % fs) / static_cast<double>(fs)};
}

StylusToolpath::StylusToolpath(CellSource& cells, const ToolpathOptions& options)
    : source_(cells), options_(options), cells_(cells.cells()), batch_(kBatch) {
  validate(options_.setup);
  check_range("cell rate", options_.cell_rate_hz, kCellRateBounds.range());
  total_samples_ = first_sample_of_cell(cells_, options_.cell_rate_hz);
  x_per_sample_ = options_.cell_rate_hz / kStylusRate_hz;
  segment_.x1 = -std::numeric_limits<double>::infinity();  // fetch a piece for the first sample
  // Lifted before the first cell.
  add_knot(-0.5, -options_.setup.lift_um);
}

void StylusToolpath::add_knot(double x, double depth) {
  if (pending_ && x - pending_x_ < kMergeGap) {
    pending_x_ = (pending_x_ + x) / 2;
    pending_depth_ = (pending_depth_ + depth) / 2;
    return;
  }
  if (pending_) curve_.push(pending_x_, pending_depth_);
  pending_ = true;
  pending_x_ = x;
  pending_depth_ = depth;
}

void StylusToolpath::feed() {
  const std::size_t n = cells_planned_ < cells_ ? source_.next(batch_) : 0;
  for (std::size_t i = 0; i < n; ++i) {
    const CellPlan plan = plan_cell(batch_[i], options_.setup);
    switch (plan.kind) {
      case CellKind::white: ++counts_.white; break;
      case CellKind::single: ++counts_.single; break;
      case CellKind::channel: ++counts_.channel; break;
      case CellKind::split: ++counts_.split; break;
    }
    if (batch_[i].line_work) ++counts_.line_work;
    const double base = static_cast<double>(cells_planned_ + i);
    for (std::uint8_t k = 0; k < plan.count; ++k) add_knot(base + plan.points[k].x, plan.points[k].depth_um);
  }
  cells_planned_ += n;
  if (n == 0 || cells_planned_ >= cells_) {
    // Lifted after the last cell (a source that ends early ends the toolpath there too).
    add_knot(static_cast<double>(cells_planned_) + 0.5, -options_.setup.lift_um);
    curve_.push(pending_x_, pending_depth_);
    pending_ = false;
    curve_.finish();
  }
}

std::size_t StylusToolpath::next(std::span<double> out) {
  const std::size_t n = static_cast<std::size_t>(std::min<std::uint64_t>(out.size(), total_samples_ - next_sample_));
  for (std::size_t k = 0; k < n; ++k) {
    const double x = (static_cast<double>(next_sample_ + k) + options_.advance_samples) * x_per_sample_;
    if (x > segment_.x1) {
      while (x > curve_.committed_x()) feed();
      segment_ = curve_.segment_at(x);
    }
    out[k] = segment_(x);
  }
  next_sample_ += n;
  return n;
}

}  // namespace mark

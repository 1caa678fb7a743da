#include "driver/sim/stylus_cells.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

#include "driver/sim/stylus_head_model.hpp"

namespace mark {
namespace {

constexpr std::uint64_t kRate = static_cast<std::uint64_t>(kStylusRate_hz);

// Fraction of the half slot between a sample and its neighbour that lies inside the cut.
double covered_half(double here, double side) {
  if (here > 0) return side > 0 ? 0.5 : std::min(0.5, here / (here - side));
  if (side > 0) return std::max(0.0, side / (side - here) - 0.5);
  return 0;
}

}  // namespace

void validate(const CellGeometry& g) {
  if (g.cell_rate_hz == 0 || g.cell_rate_hz > kRate / 2)
    throw std::invalid_argument("cell rate " + std::to_string(g.cell_rate_hz) + " Hz is outside 1 .. " +
                                std::to_string(kRate / 2) + " Hz");
  if (!(g.cell_pitch_um > 0 && std::isfinite(g.cell_pitch_um)))
    throw std::invalid_argument("cell pitch must be a positive number of micrometres");
  if (!(g.stylus_angle_deg >= 10 && g.stylus_angle_deg <= 170))
    throw std::invalid_argument("stylus angle " + std::to_string(g.stylus_angle_deg) +
                                "° is outside 10 .. 170°");
}

std::uint64_t first_sample_of_cell(std::uint64_t cell, std::uint32_t rate) {
  return (cell * kRate + rate - 1) / rate;
}

std::uint64_t cell_of_sample(std::uint64_t sample, std::uint32_t rate) { return sample * rate / kRate; }

CellMeter::CellMeter(const CellGeometry& g, std::size_t max_cells)
    : geometry_(g),
      slot_um_(g.cell_pitch_um * g.cell_rate_hz / kStylusRate_hz),
      half_width_(std::tan(g.stylus_angle_deg * std::numbers::pi / 360)),
      max_cells_(max_cells) {
  validate(g);
  cells_.reserve(max_cells_);
  clear();
}

void CellMeter::clear() {
  cells_.clear();
  current_ = {};
  cell_ = 0;
  next_first_ = first_sample_of_cell(1, geometry_.cell_rate_hz);
  sample_ = 0;
  seen_ = 0;
  prev_ = cur_ = 0;
  dropped_ = 0;
}

void CellMeter::add(float cut_um) {
  if (seen_++ == 0) {
    cur_ = cut_um;
    return;
  }
  measure(prev_, cur_, cut_um);
  prev_ = cur_;
  cur_ = cut_um;
}

void CellMeter::finish() {
  if (seen_ == 0) return;
  measure(prev_, cur_, 0);
  close_cell();
  seen_ = 0;  // a second finish() adds nothing
}

void CellMeter::measure(float left, float here, float right) {
  while (sample_ >= next_first_) {
    close_cell();
    ++cell_;
    next_first_ = first_sample_of_cell(cell_ + 1, geometry_.cell_rate_hz);
  }
  ++sample_;
  const double c = std::max(0.0f, here);
  current_.depth_um = std::max(current_.depth_um, static_cast<float>(c));
  current_.length_um += static_cast<float>((covered_half(here, left) + covered_half(here, right)) * slot_um_);
  current_.area_um2 += static_cast<float>(2 * half_width_ * c * slot_um_);
  current_.volume_um3 += static_cast<float>(half_width_ * c * c * slot_um_);
}

void CellMeter::close_cell() {
  if (cells_.size() < max_cells_)
    cells_.push_back(current_);
  else
    ++dropped_;
  current_ = {};
}

std::vector<CellFigures> measure_cells(std::span<const float> cut_um, const CellGeometry& geometry) {
  const std::size_t cells = cut_um.empty() ? 0 : cell_of_sample(cut_um.size() - 1, geometry.cell_rate_hz) + 1;
  CellMeter meter(geometry, cells);
  for (float c : cut_um) meter.add(c);
  meter.finish();
  return meter.cells();
}

}  // namespace mark

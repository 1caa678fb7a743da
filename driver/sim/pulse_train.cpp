#include "driver/sim/pulse_train.hpp"

#include <algorithm>

namespace mark {

void PulseTrain::begin(double frequency_khz, double spot_diameter_um, DoseRaster* raster) {
  *this = PulseTrain{};
  raster_ = raster;
  frequency_khz_ = frequency_khz;
  spot_um_ = spot_diameter_um;
  period_s_ = 1 / (frequency_khz * 1e3);
}

void PulseTrain::step(Vec2 p0, Vec2 p1, double dt, bool gate, double power) {
  if (!gate) {
    open_ = false;
    have_last_ = false;
    return;
  }
  if (!open_) {
    open_ = true;
    since_s_ = period_s_;  // the gate opening fires the first pulse at p0
  }
  // Pulses due within this sub-step, at the beam's position when each fires (linear within
  // the sub-step, as the integrator moves it).
  double t = period_s_ - since_s_;  // from the start of the sub-step to the next pulse
  for (; t <= dt; t += period_s_) {
    const Vec2 at = p0 + (dt > 0 ? t / dt : 0.0) * (p1 - p0);
    if (have_last_) {
      const double gap = norm(at - last_);
      gap_sum_mm_ += gap;
      gap_max_mm_ = std::max(gap_max_mm_, gap);
      ++gaps_;
    }
    if (raster_ && power > 0) raster_->deposit(at, power * period_s_);
    last_ = at;
    have_last_ = true;
    ++pulses_;
  }
  since_s_ = period_s_ - (t - dt);
}

PulseFigures PulseTrain::figures() const {
  PulseFigures f;
  f.frequency_khz = frequency_khz_;
  f.spot_diameter_um = spot_um_;
  f.pulses = pulses_;
  f.spacing_max_um = gap_max_mm_ * 1e3;
  f.spacing_mean_um = gaps_ ? gap_sum_mm_ / static_cast<double>(gaps_) * 1e3 : 0;
  return f;
}

}  // namespace mark

#include "driver/sim/plant_effects.hpp"

#include <cmath>
#include <numbers>

namespace mark {

Vec2 quantised(Vec2 p, double field_mm, int bits) {
  if (bits <= 0) return p;
  const double codes = std::ldexp(1.0, bits) - 1;  // code 0 at −field/2, the last at +field/2
  const double half = field_mm / 2;
  auto q = [&](double v) { return std::round((v + half) / field_mm * codes) * field_mm / codes - half; };
  return {q(p.x), q(p.y)};
}

CommandHistory::CommandHistory(int substeps, int delay_substeps)
    : substeps_(substeps), delay_(delay_substeps), ring_(static_cast<std::size_t>(delay_substeps / substeps + 3)) {}

void CommandHistory::start(Vec2 at) {
  start_ = at;
  pushed_ = 0;
}

void CommandHistory::push(Vec2 s) {
  ring_[static_cast<std::size_t>(pushed_ % static_cast<std::int64_t>(ring_.size()))] = s;
  ++pushed_;
}

Vec2 CommandHistory::sample(std::int64_t k) const {
  if (k < 0) return start_;
  return ring_[static_cast<std::size_t>(k % static_cast<std::int64_t>(ring_.size()))];
}

// Sub-step j of tick k (the newest) is global sub-step g = k·n + j; delayed, g − delay lies in
// tick g' / n at sub-step g' mod n, where the command runs from sample k'−1 to sample k'.
std::int64_t CommandHistory::delayed(int j) const { return (pushed_ - 1) * substeps_ + j - delay_; }

Vec2 CommandHistory::at(int j) const {
  const std::int64_t g = delayed(j), n = substeps_;
  if (g < 0) return start_;
  const Vec2 from = sample(g / n - 1), to = sample(g / n);
  return from + (static_cast<double>(g % n) / static_cast<double>(n)) * (to - from);
}

Vec2 CommandHistory::tick_move(int j) const {
  const std::int64_t g = delayed(j);
  if (g < 0) return {0, 0};
  return sample(g / substeps_) - sample(g / substeps_ - 1);
}

MirrorResonance::MirrorResonance(double hz, double zeta, double dt) {
  if (!(hz > 0)) return;
  wr_ = 2 * std::numbers::pi * hz;
  step_ = second_order_step(wr_, zeta, dt);
}

Vec2 MirrorResonance::step(Vec2 a) {
  // Constant forcing −a: the twist's rest point is r = −a/ωr², and the step is exact about it.
  const double rest[2] = {-a.x / (wr_ * wr_), -a.y / (wr_ * wr_)};
  for (int i = 0; i < 2; ++i) step_.apply(r_[i], v_[i], rest[i]);
  return {r_[0], r_[1]};
}

BeamNoise::BeamNoise(double rms_mm, double corr_s, double dt) : rms_(rms_mm) {
  rho_ = std::exp(-dt / corr_s);
  kick_ = rms_ * std::sqrt(1 - rho_ * rho_);
}

void BeamNoise::start(std::uint64_t seed) {
  rng_.seed(seed);
  has_spare_ = false;
  n_ = {rms_ * gauss(), rms_ * gauss()};
}

Vec2 BeamNoise::step() {
  n_.x = rho_ * n_.x + kick_ * gauss();
  n_.y = rho_ * n_.y + kick_ * gauss();
  return n_;
}

double BeamNoise::gauss() {
  if (has_spare_) {
    has_spare_ = false;
    return spare_;
  }
  // Two uniforms in (0, 1] from the top 53 bits each.
  const double u1 = (static_cast<double>(rng_() >> 11) + 1) * 0x1p-53;
  const double u2 = static_cast<double>(rng_() >> 11) * 0x1p-53;
  const double r = std::sqrt(-2 * std::log(u1));
  spare_ = r * std::sin(2 * std::numbers::pi * u2);
  has_spare_ = true;
  return r * std::cos(2 * std::numbers::pi * u2);
}

CoilHeat::CoilHeat(double limit_share, double tau_s, double dt)
    : limit_(limit_share), keep_(tau_s > 0 ? std::exp(-dt / tau_s) : 0) {}

bool CoilHeat::step(Vec2 accel_share) {
  const double sq[2] = {accel_share.x * accel_share.x, accel_share.y * accel_share.y};
  bool over = false;
  for (int i = 0; i < 2; ++i) {
    mean_sq_[i] = sq[i] + (mean_sq_[i] - sq[i]) * keep_;
    over = over || mean_sq_[i] > limit_ * limit_;
  }
  return over;
}

double CoilHeat::rms_share(int axis) const { return std::sqrt(mean_sq_[axis]); }

}  // namespace mark

#pragma once
// The parts of the plant (plant.hpp) that sit around the servo loop of the simulated scanner: the
// command quantised and delayed before the servo sees it, and the beam displaced after it by the
// mirror's resonance and by noise. Each is a small state machine stepped once per sub-step by
// SimScanner::follow; with the plant at its defaults each is the identity.
#include <cstdint>
#include <random>
#include <vector>

#include "driver/sim/plant.hpp"
#include "driver/sim/second_order_step.hpp"
#include "driver/vec2.hpp"

namespace mark {

// The sample rounded to one of 2^bits codes across the field (centred on 0), as a 16-bit XY2-100
// head receives it; bits = 0 leaves it exact.
Vec2 quantised(Vec2 sample, double field_mm, int bits);

// The command the servo sees at every sub-step: the samples, linear within each tick (first-
// order hold), `delay` sub-steps late. Keeps only the samples the delay reaches back to, sized
// once, so the drain thread never allocates.
class CommandHistory {
 public:
  CommandHistory(int substeps, int delay_substeps);
  // Before the first sample (and for the delay's first sub-steps) the command is `at`.
  void start(Vec2 at);
  void push(Vec2 sample);  // the command for the end of the next tick
  // The command at the start of sub-step j (0 ≤ j < substeps) of the newest tick, and how far
  // the command moves over the tick that sub-step lies in.
  Vec2 at(int j) const;
  Vec2 tick_move(int j) const;
  Vec2 newest() const { return sample(pushed_ - 1); }

 private:
  Vec2 sample(std::int64_t k) const;  // sample k of this history; before the first: the start
  std::int64_t delayed(int j) const;  // global sub-step the servo sees at sub-step j (< 0: before the start)
  int substeps_, delay_;
  std::vector<Vec2> ring_;
  std::int64_t pushed_ = 0;
  Vec2 start_{0, 0};
};

// The mirror twisting against the shaft: r̈ + 2ζ·ωr·ṙ + ωr²·r = −(shaft acceleration), per axis,
// exact over each sub-step with the shaft's mean acceleration over it.
class MirrorResonance {
 public:
  MirrorResonance(double hz, double zeta, double dt);
  bool active() const { return wr_ > 0; }
  // The shaft's acceleration over this sub-step; returns the mirror's offset from the shaft.
  Vec2 step(Vec2 shaft_accel);
  void reset() { r_[0] = r_[1] = v_[0] = v_[1] = 0; }

 private:
  double wr_ = 0;
  SecondOrderStep step_;
  double r_[2] = {0, 0}, v_[2] = {0, 0};
};

// Beam position noise: per axis an Ornstein–Uhlenbeck process of rms `rms_mm` and correlation
// time `corr_s`, from a 64-bit Mersenne Twister (a sequence the C++ standard fixes) and the
// Box–Muller transform (written out: std::normal_distribution differs between libraries), so a
// seed gives the same noise everywhere.
class BeamNoise {
 public:
  BeamNoise(double rms_mm, double corr_s, double dt);
  bool active() const { return rms_ > 0; }
  void start(std::uint64_t seed);  // drawn from the stationary distribution
  Vec2 step();                     // the offset after one more sub-step
  Vec2 offset() const { return n_; }

 private:
  double gauss();
  double rms_ = 0, rho_ = 0, kick_ = 0;
  std::mt19937_64 rng_;
  double spare_ = 0;
  bool has_spare_ = false;
  Vec2 n_{0, 0};
};

// The coils' heating: per axis the mean square of the shaft's acceleration over an exponential
// window of the thermal time constant (exact over each sub-step for the sub-step's value), which
// is the coil's i²R heat as a share of the heat at peak current. A drive trips when its root
// passes the limit share of the peak acceleration.
class CoilHeat {
 public:
  // limit_share 0: none.
  CoilHeat(double limit_share, double tau_s, double dt);
  bool active() const { return limit_ > 0; }
  void reset() { mean_sq_[0] = mean_sq_[1] = 0; }
  // The axes' accelerations over this sub-step as shares of their peak; true once an axis is
  // past the limit.
  bool step(Vec2 accel_share);
  // An axis's rms acceleration as a share of its peak, now, and the axis that tripped (0 x, 1 y).
  double rms_share(int axis) const;
  int hottest_axis() const { return mean_sq_[1] > mean_sq_[0] ? 1 : 0; }

 private:
  double limit_ = 0, keep_ = 1;
  double mean_sq_[2] = {0, 0};
};

}  // namespace mark

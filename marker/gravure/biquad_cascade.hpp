#pragma once
// The tuning processor's filter loop: every stylus sample runs through the designed sections in
// series, each a biquad in transposed direct form II (two state variables per section, the form
// with the best numerical behaviour for poles this close to the unit circle in double
// precision), then the bank's overall gain.
//
//   y = b0·x + s1;   s1 = b1·x − a1·y + s2;   s2 = b2·x − a2·y
#include <span>
#include <vector>

#include "marker/gravure/tuning_filter.hpp"

namespace mark {

class BiquadCascade {
 public:
  BiquadCascade() = default;
  explicit BiquadCascade(const FilterBank& bank, double tick_s = kStylusTick_s);

  // Filters the samples in place; the state carries over to the next call.
  void process(std::span<double> samples);
  // Starts the state at rest with input x (the steady state for a constant x: no start-up ring).
  void settle(double x);
  void reset() { settle(0); }

  std::size_t sections() const { return coefficients_.size(); }
  const std::vector<BiquadCoefficients>& coefficients() const { return coefficients_; }

 private:
  std::vector<BiquadCoefficients> coefficients_;
  std::vector<double> state_;  // s1, s2 of each section
  double gain_ = 1;
};

}  // namespace mark

#pragma once
// An input shaper: the locus convolved with a few impulses spaced half a resonance period apart,
// so that what one impulse starts ringing in a lightly damped mirror the next cancels
// (Singer & Seering's ZV and ZVD shapers). A real galvo's mirror twists against its motor shaft
// at 5–15 kHz with ζ of a few hundredths; feed-forward cannot take that out, since the planner's
// head model has no such mode, and every step in the planned acceleration rings it
// (docs/speed.md, "Input shaping").
//
// The shaper delays and smooths the command. Neither is left to show in the mark:
//  - the laser bit and power are delayed by the shaper's mean delay rounded to a whole tick;
//  - the fraction of a tick left over and the shaper's spread (its variance σ²: a curve taken
//    at acceleration a comes out σ²·a/2 inside) are put into the feed-forward terms, so the
//    shaped command is the planned path, to second order, that many ticks later.
#include <cstdint>
#include <string_view>
#include <vector>

#include "marker/plan/pen.hpp"

namespace mark {

struct InputShaper {
  // Weights of the locus samples k, k−1, k−2, … in the shaped sample k (they sum to 1). Empty:
  // no shaping.
  std::vector<double> taps;
  // Whole ticks the laser bit and power are delayed by: the taps' mean delay, rounded.
  std::uint32_t delay_ticks = 0;
  // The feed-forward terms the planned locus uses under this shaper (the pen's own when off).
  double lag_s = 0;
  double inertia_s2 = 0;

  bool active() const { return taps.size() > 1; }
  // Samples the shaped locus has beyond the planned one: the command settles on the last point.
  std::uint32_t tail_ticks() const { return taps.empty() ? 0 : static_cast<std::uint32_t>(taps.size() - 1); }
};

// The highest resonance a shaper can be designed for at this tick: a quarter of the tick rate,
// so the impulses half a period apart are at least two ticks apart (closer, the split between
// ticks no longer places them where the resonance needs them).
inline double max_shaper_hz(double tick_s) { return 0.25 / tick_s; }

// The pen's shaper (none when pen.shaper_hz is 0). Its impulses fall between ticks: each is
// split between the two ticks around it in proportion, which keeps the taps' mean delay exact.
InputShaper design_input_shaper(const Pen& pen);

// "zv" or "zvd"; throws InputError naming the value otherwise.
ShaperKind parse_shaper_kind(std::string_view name);
std::string_view to_string(ShaperKind kind);

}  // namespace mark

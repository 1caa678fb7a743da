#pragma once
// The pulses of a Q-switched or MOPA fiber laser along the beam's real path. While the laser
// gate is open the source fires every 1/f — the first pulse as the gate opens — so at speed v
// pulses land v/f apart (dynamics.md §4.2: pitch p = v/f, overlap O = 1 − p/d against the spot
// diameter d). The simulator's dose raster is the time average of these pulses; that average
// stands for the mark only while neighbouring pulses overlap. Below zero overlap a lit stroke
// shows as a row of separate dots, which the figures flag. Given a raster, the train also lays
// each pulse's dose where it fires: the part as a camera sees it, scallops and dots included
// (the quality figures keep the time average, whose disc sums do not ripple with the pitch).
//
// Called on the drain thread once per integration sub-step: no allocation, a few flops.
#include <cstdint>

#include "driver/sim/dose_raster.hpp"
#include "driver/vec2.hpp"

namespace mark {

struct PulseFigures {
  double frequency_khz = 0;
  double spot_diameter_um = 0;
  std::uint64_t pulses = 0;     // fired in the job
  // Between consecutive pulses of one lit run (the gate open throughout): the widest gap and
  // the mean gap. 0 when no run had two pulses.
  double spacing_max_um = 0;
  double spacing_mean_um = 0;

  // Overlap of the widest gap: 1 = pulses on top of each other, 0 = touching, < 0 = dots.
  double overlap() const {
    return spot_diameter_um > 0 ? 1 - spacing_max_um / spot_diameter_um : 1;
  }
  bool separate_dots() const { return overlap() < 0; }
};

class PulseTrain {
 public:
  // A new job: no pulses yet. frequency_khz > 0. With a raster, each pulse's dose goes into it
  // (the caller clears and reserves it).
  void begin(double frequency_khz, double spot_diameter_um, DoseRaster* raster = nullptr);
  // The beam moved p0 → p1 during dt with the gate open (pulses fire) or closed (the train
  // stops; the next opening fires at once and starts a new run). power: the light's mean share
  // of full power over the step; a pulse carries power × period (seconds at full power, the
  // dose raster's unit), so the pulses' sum is the time average's.
  void step(Vec2 p0, Vec2 p1, double dt, bool gate, double power = 0);
  PulseFigures figures() const;

 private:
  double frequency_khz_ = 30;
  double spot_um_ = 40;
  double period_s_ = 1 / 30e3;
  DoseRaster* raster_ = nullptr;
  double since_s_ = 0;        // time since the last pulse of the open run
  bool open_ = false;
  bool have_last_ = false;    // a pulse fired in this run
  Vec2 last_{0, 0};           // where it landed
  std::uint64_t pulses_ = 0;
  std::uint64_t gaps_ = 0;
  double gap_sum_mm_ = 0;
  double gap_max_mm_ = 0;
};

}  // namespace mark

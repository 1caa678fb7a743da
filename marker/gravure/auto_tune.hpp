#pragma once
// Automatic tuning (US 6,007,230 FIG. 8, blocks 230–238): run the head response test on the
// head — measured from the sensing coil's position and velocity together, by default (see
// stylus_head_response.hpp) — fit its resonances, recompute the filter coefficients from the fit, and check the
// result the way the operator would — a second response test with the new filters in the path,
// which must be flat within ±1 dB from 0 to 10 kHz (FIG. 11). Both tests go through the line
// memory and the fixed-rate drain like any stylus job.
#include <functional>
#include <vector>

#include "driver/sim/sim_stylus_head.hpp"
#include "marker/gravure/head_design.hpp"
#include "marker/gravure/stylus_head_fit.hpp"
#include "marker/gravure/stylus_head_response.hpp"
#include "marker/gravure/stylus_run.hpp"

namespace mark {

struct AutoTuneOptions {
  SweepOptions identify;                   // the head alone
  SweepOptions verify{100, 10000, 40};     // filters × head, 100 Hz .. 10 kHz
  TargetResponse target;
  int modes = 0;                           // 0: as many as the response shows
  ResponseSource source = ResponseSource::fused;  // what both tests measure the response from
  double tolerance_db = 1;
  StylusRunOptions run;                    // virtual time, stop flag
};

struct AutoTuneResult {
  HeadFit fit;
  FilterBank bank;
  std::vector<ResponsePoint> raw_response;    // head alone
  std::vector<ResponsePoint> tuned_response;  // filters × head
  Flatness flatness;                          // of tuned_response, relative to its first tone
  bool within_tolerance = false;
  double test_time_s = 0;                     // device time of both tests
  bool cancelled = false;
};

// The head records its sensing coil for the two tests and the cut profile again afterwards.
// Throws InputError when the fit fails, DeviceFaultError when the head faults.
AutoTuneResult auto_tune(SimStylusHead& head, const AutoTuneOptions& options = {});

// The gain of a response relative to its first point, min and max in dB.
Flatness measured_flatness(const std::vector<ResponsePoint>& response);

}  // namespace mark

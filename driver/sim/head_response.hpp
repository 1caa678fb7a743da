#pragma once
// The head response test: a command pattern that makes a scan head show its dynamics, and its
// recorded answer. driver/ drives the head and records where the mirrors went; marker/head/
// fits a model to the record (first-order τ, second-order ωn and ζ, speed and acceleration
// limits). The pattern depends only on the field and the tick, never on the head's own
// parameters, so nothing of the answer leaks into the question.
//
// Parts (each starts and ends at rest after a hold long enough for the slowest head to settle):
//   small steps   ±2, ±5, ±10 µm on x: the linear step response (overshoot, rise)
//   ramps         20, 50, 100 mm/s on x for 2 ms and back: the ramp lag
//   chirp         5 µm amplitude, 100 Hz → 3 kHz over 30 ms on x: the frequency response
//   large steps   2 %, 10 % and 45 % of the field, on x and on y: speed and acceleration limits
// Small parts stay far below any head's limits, so they see the linear servo alone.
#include <cstddef>
#include <vector>

#include "driver/sim/sim_scanner.hpp"
#include "driver/vec2.hpp"
#include "ringbuffer/scan_sample.hpp"

namespace mark {

enum class ResponsePartKind { small_step, ramp, chirp, large_step };

struct ResponsePart {
  ResponsePartKind kind;
  int axis = 0;              // 0: x, 1: y
  std::size_t first = 0;     // first sample of the part (the hold before it belongs to it)
  std::size_t count = 0;     // samples
  double size_mm = 0;        // step size, ramp length or chirp amplitude
};

struct ResponsePattern {
  double tick_s = 10e-6;
  std::vector<ScanSample> commands;  // laser off throughout
  std::vector<ResponsePart> parts;
};

// The pattern for a head with this field (mm, square, centred) at this tick.
ResponsePattern head_response_pattern(double field_mm, double tick_s = 10e-6);

struct ResponseRecord {
  ResponsePattern pattern;
  // Beam position at the end of every tick: position[k] is where the mirrors were when the
  // command commands[k] had been applied for one tick (the head's position output, sampled at
  // the command rate as SL2-100 heads report it).
  std::vector<Vec2> position;
};

// Runs the pattern on the simulated head (from rest at the field centre, laser off) and records
// its position output. Throws DeviceError if the head refuses the pattern (field too small).
ResponseRecord measure_head_response(const SimScannerOptions& head_options,
                                     const ResponsePattern& pattern);

}  // namespace mark

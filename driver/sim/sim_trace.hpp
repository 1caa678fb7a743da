#pragma once
// One row of the simulated scanner's trace (`marker mark --trace FILE.csv`): per sample, the
// command the device received and where the simulated beam was at the end of that tick, so
// anyone can plot what the head did.
namespace mark {

struct SimTraceRow {
  double t_s;          // device time at the end of the tick
  float cmd_x_mm, cmd_y_mm;
  bool laser;          // laser gate as commanded
  float beam_x_mm, beam_y_mm;
};

}  // namespace mark

#pragma once
// Refusals before the first sample: a job is only started when everything it will command is
// inside the head's field (the figure plus blanking lines, run-ins, run-outs and jumps) and its
// speeds and tick are within the head's limits. Each refusal is one InputError naming the input.
#include "driver/device.hpp"
#include "driver/sim/head_model.hpp"
#include "marker/plan/plan.hpp"

namespace mark {

// Shortest tick the simulated devices integrate meaningfully (the RTC laser-delay resolution).
inline constexpr double kMinTick_s = 1e-6;

// Pen limits alone (speeds, tick against the head): usable before planning.
void check_pen(const Pen& pen, const HeadModel& head);
// Everything: the pen, that the plan marks something, and that every command stays in the field.
void check_plan(const Plan& plan, const HeadModel& head);
// The job's field (the head's, --field, a job file's field_mm) against the device's: checked when
// a job meets its device, and by a production job's runner before it takes any serial.
void check_field(const HeadModel& head, const DeviceDescription& device);

}  // namespace mark

#include "marker/gravure/auto_tune.hpp"

#include <algorithm>
#include <cmath>

#include "driver/device.hpp"

namespace mark {
namespace {

// One response test: the pattern (through the bank, if any) into the head, sensing recorded.
// Empty when cancelled.
std::vector<ResponsePoint> response_test(SimStylusHead& head, const SweepOptions& sweep, const FilterBank* bank,
                                         ResponseSource source, StylusRunOptions run, double& device_time_s,
                                         bool& cancelled) {
  SweepPattern pattern(sweep);
  head.set_recording(false, true);
  run.job_name = bank ? "head response test (tuned)" : "head response test";
  const StylusRunResult r = run_stylus_job(pattern, bank, head, run);
  head.reset();
  device_time_s += r.report.device_time_s;
  if (r.fault) throw DeviceFaultError(*r.fault);
  if (r.cancelled || r.report.outcome != DeviceState::done) {
    cancelled = true;
    return {};
  }
  switch (source) {
    case ResponseSource::position: return pattern.measure(head.sensed_position_um());
    case ResponseSource::velocity: return pattern.measure_velocity(head.sensed_velocity_um_s());
    case ResponseSource::fused: break;
  }
  return pattern.measure(head.sensed_position_um(), head.sensed_velocity_um_s());
}

}  // namespace

Flatness measured_flatness(const std::vector<ResponsePoint>& response) {
  Flatness fl{0, 0};
  if (response.empty()) return fl;
  const double ref = std::abs(response.front().gain);
  for (const ResponsePoint& p : response) {
    const double db = 20 * std::log10(std::abs(p.gain) / ref);
    fl.min_db = std::min(fl.min_db, db);
    fl.max_db = std::max(fl.max_db, db);
  }
  return fl;
}

AutoTuneResult auto_tune(SimStylusHead& head, const AutoTuneOptions& o) {
  AutoTuneResult r;
  const bool profile = head.options().record_profile, sense = head.options().record_sense;
  r.raw_response = response_test(head, o.identify, nullptr, o.source, o.run, r.test_time_s, r.cancelled);
  if (!r.cancelled) {
    r.fit = fit_head(r.raw_response, o.modes);
    r.bank = design_for_head(r.fit.model, o.target);
    r.tuned_response = response_test(head, o.verify, &r.bank, o.source, o.run, r.test_time_s, r.cancelled);
    r.flatness = measured_flatness(r.tuned_response);
    r.within_tolerance = !r.cancelled && r.flatness.min_db >= -o.tolerance_db && r.flatness.max_db <= o.tolerance_db;
  }
  head.set_recording(profile, sense);
  return r;
}

}  // namespace mark

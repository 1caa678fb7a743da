#include "marker/job/job_json.hpp"

#include "driver/sim/quality_class.hpp"

namespace mark {

nlohmann::json quality_json(const Quality& q, const std::optional<PulseFigures>& pulses) {
  nlohmann::json j = {{"max_deviation_um", q.max_deviation_um},
                      {"rms_deviation_um", q.rms_deviation_um},
                      {"coverage_fraction", q.coverage},
                      {"dose_ratio_max", q.dose_ratio_max},
                      {"overshoot_um", q.overshoot_um},
                      {"pulse_gap_max_um", q.pulse_gap_max_um},
                      {"dose_per_mm_fraction", q.dose_per_mm_fraction},
                      {"dose_reference", q.dose_vs_material ? "material" : "pen"},
                      {"material_dose_per_mm_fraction", q.material_dose_per_mm_fraction},
                      {"class", to_string(classify(q))}};
  if (pulses) j["separate_dots"] = pulses->separate_dots();
  return j;
}

nlohmann::json job_result_json(const JobResult& r) {
  nlohmann::json j = {{"outcome", to_string(r.outcome)},
                      {"ink_marked_fraction", r.ink_marked},
                      {"glyphs", r.glyphs},
                      {"strokes", r.strokes},
                      {"commands", r.commands},
                      {"samples", r.samples},
                      {"mark_time_s", r.mark_time_s},
                      {"compile_time_s", r.compile_time_s},
                      {"wall_time_s", r.wall_time_s},
                      {"underruns", r.drain.underrun_events},
                      {"underrun_samples", r.drain.underrun_samples},
                      {"jump_length_mm", r.jump_length_mm},
                      {"peak_fill_samples", r.drain.peak_fill},
                      {"lateness_p99_us", r.drain.lateness_p99_us},
                      {"lateness_max_us", r.drain.lateness_max_us},
                      {"realtime", {{"sched_fifo", r.drain.realtime_granted},
                                    {"memory_locked", r.memory_locked}}}};
  if (r.outcome != JobOutcome::done) j["stopped_at"] = r.stopped_at;
  if (r.fault)
    j["fault"] = {{"category", to_string(r.fault->category)},
                  {"message", r.fault->message},
                  {"at", r.fault->at}};
  if (r.stop_latency_us >= 0) {
    j["stop_latency_us"] = r.stop_latency_us;
    j["stop_latency_samples"] = r.stop_latency_samples;
  }
  nlohmann::json figures = nlohmann::json::object();
  for (const auto& [name, value] : r.device.figures) figures[name] = value;
  j["device_figures"] = figures;
  if (r.quality) j["quality"] = quality_json(*r.quality, r.pulses);
  if (r.pulses) {
    j["pulse_spacing_um"] = r.pulses->spacing_max_um;
    j["pulse_overlap_fraction"] = r.pulses->overlap();
  }
  return j;
}

}  // namespace mark

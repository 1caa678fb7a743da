#include "marker/gravure/gravure_json.hpp"

#include <cmath>
#include <numbers>

#include "driver/sim/stylus_head_model.hpp"
#include "marker/gravure/head_design.hpp"

namespace mark {
namespace {

nlohmann::json error_json(const DepthError& e) { return {{"rms", e.rms_um}, {"max", e.max_um}}; }

nlohmann::json cell_error_json(const CellError& e) {
  return {{"depth_rms_um", e.depth_rms_um}, {"length_rms_um", e.length_rms_um}, {"volume_rms_pct", e.volume_rms_pct}};
}

nlohmann::json response_json(const std::vector<ResponsePoint>& r) {
  nlohmann::json a = nlohmann::json::array();
  for (const ResponsePoint& p : r)
    a.push_back({{"freq_hz", p.freq_hz},
                 {"gain_db", 20 * std::log10(std::abs(p.gain))},
                 {"phase_deg", std::arg(p.gain) * 180 / std::numbers::pi},
                 {"velocity_weight", p.velocity_weight}});
  return a;
}

nlohmann::json flatness_json(const Flatness& f) { return {{"min", f.min_db}, {"max", f.max_db}}; }

}  // namespace

nlohmann::json to_json(const StylusHeadModel& head) {
  nlohmann::json modes = nlohmann::json::array();
  for (const StylusMode& m : head.modes)
    modes.push_back({{"freq_hz", m.freq_hz}, {"damping", m.damping}, {"gain", m.gain}});
  return modes;
}

nlohmann::json to_json(const FilterBank& bank) {
  nlohmann::json sections = nlohmann::json::array();
  for (const FilterSection& s : bank.sections) {
    const MatchedZ z = matched_z(s.zero_hz, s.zero_damping), p = matched_z(s.pole_hz, s.pole_damping);
    const BiquadCoefficients c = design(s);
    nlohmann::json j = {{"kind", std::string(to_string(s.kind))},
                        {"zero_hz", s.zero_hz},
                        {"zero_damping", s.zero_damping},
                        {"pole_hz", s.pole_hz},
                        {"pole_damping", s.pole_damping},
                        {"c1_zero", z.c1},
                        {"c2_zero", z.c2},
                        {"c1_pole", p.c1},
                        {"c2_pole", p.c2},
                        {"b", {c.b0, c.b1, c.b2}},
                        {"a", {1.0, c.a1, c.a2}}};
    if (s.kind == SectionKind::notch && s.zero_hz == s.pole_hz && s.zero_damping > 0)
      j["notch_depth_db"] = 20 * std::log10(s.pole_damping / s.zero_damping);
    sections.push_back(j);
  }
  return {{"gain", bank.gain}, {"sections", sections}};
}

nlohmann::json to_json(const GravureJobSpec& spec, const GravureReport& r) {
  const GravureLayout& g = r.layout;
  nlohmann::json j;
  j["image"] = {{"width_px", spec.image.width},
                {"height_px", spec.image.height},
                {"width", r.width_mm},
                {"height", r.height_mm},
                {"resolution_px_mm", r.px_per_mm},
                {"line_work_mask", spec.mask.has_value()}};
  j["screen"] = {{"cells_per_mm_along", spec.screen.cells_per_mm_along},
                 {"cells_per_mm_across", spec.screen.cells_per_mm_across},
                 {"cell_pitch_um", g.cell_pitch_um},
                 {"track_pitch_um", g.track_pitch_um},
                 {"stagger", g.stagger},
                 {"cell_rate_hz", g.cell_rate_hz},
                 {"samples_per_cell", kStylusRate_hz / g.cell_rate_hz}};
  j["tracks"] = g.tracks;
  j["cells_per_track"] = g.cells_per_track;
  j["cells"] = r.cells;
  j["cell_kinds"] = {{"white", r.counts.white},
                     {"single", r.counts.single},
                     {"channel", r.counts.channel},
                     {"split", r.counts.split},
                     {"line_work", r.counts.line_work}};
  j["samples"] = r.samples;
  j["stylus_rate_hz"] = kStylusRate_hz;
  j["engrave_time_s"] = r.filtered.run.report.device_time_s;
  j["wall_time_s"] = r.wall_time_s;
  j["outcome"] = std::string(to_string(r.filtered.run.report.outcome));
  j["cancelled"] = r.cancelled;
  j["underruns"] = r.filtered.run.drain.underrun_events;
  j["advance_samples"] = r.filtered.advance_samples;
  j["drive_peak_um"] = r.filtered.drive_peak_um;
  j["max_cut_um"] = r.filtered.max_cut_um;
  j["depth_error_um"] = error_json(r.filtered.depth_error);
  j["cell_error"] = cell_error_json(r.filtered.cell_error);
  // Against what the image asked for (not the toolpath's own curve): issue 23.
  j["depth_error_vs_cells_rms_um"] = r.filtered.depth_error_vs_cells.rms_um;
  j["depth_error_vs_cells_max_um"] = r.filtered.depth_error_vs_cells.max_um;
  j["full_cell_depth_um"] = r.full_cell_depth_um;
  if (r.unfiltered) {
    j["depth_error_vs_cells_unfiltered_rms_um"] = r.unfiltered->depth_error_vs_cells.rms_um;
    j["depth_error_vs_cells_unfiltered_max_um"] = r.unfiltered->depth_error_vs_cells.max_um;
    j["depth_error_unfiltered_um"] = error_json(r.unfiltered->depth_error);
    j["cell_error_unfiltered"] = cell_error_json(r.unfiltered->cell_error);
    j["drive_peak_unfiltered_um"] = r.unfiltered->drive_peak_um;
    if (r.filtered.depth_error.rms_um > 0)
      j["depth_error_ratio"] = r.unfiltered->depth_error.rms_um / r.filtered.depth_error.rms_um;
  }
  j["setup"] = {{"ct", {{"full_cell_depth_um", spec.setup.ct.full_cell_depth_um},
                        {"channel_depth_um", spec.setup.ct.channel_depth_um},
                        {"gain", spec.setup.ct.gain},
                        {"offset_um", spec.setup.ct.offset_um}}},
                {"lw", {{"full_cell_depth_um", spec.setup.lw.full_cell_depth_um},
                        {"channel_depth_um", spec.setup.lw.channel_depth_um},
                        {"gain", spec.setup.lw.gain},
                        {"offset_um", spec.setup.lw.offset_um}}},
                {"lift_um", spec.setup.lift_um},
                {"stylus_angle_deg", spec.stylus_angle_deg}};
  j["head"] = {{"modes", to_json(spec.head.head)},
               {"sense_noise_um", spec.head.sense_noise_um},
               {"sense_velocity_noise_um_s", spec.head.sense_velocity_noise_um_s}};
  nlohmann::json filters = to_json(r.bank);
  filters["source"] = std::string(to_string(r.filters));
  if (r.filters != FilterChoice::off) {
    filters["designed_for"] = to_json(r.design_head);
    filters["predicted_flatness_db"] = flatness_json(predicted_flatness(r.bank, spec.head.head));
  }
  j["filters"] = filters;
  if (r.tuning) {
    const AutoTuneResult& t = *r.tuning;
    j["tuning"] = {{"source", std::string(to_string(spec.tuning.source))},
                   {"fitted", to_json(t.fit.model)},
                   {"fit_rms_relative_error", t.fit.rms_relative_error},
                   {"flatness_db", flatness_json(t.flatness)},
                   {"within_tolerance", t.within_tolerance},
                   {"test_time_s", t.test_time_s},
                   {"raw_response", response_json(t.raw_response)},
                   {"tuned_response", response_json(t.tuned_response)}};
  }
  return j;
}

}  // namespace mark

#include "marker/codes/code_json.hpp"

namespace mark {
namespace {

// JSON strings must be UTF-8: bytes that are not (binary data) become U+FFFD; data_match
// compares the bytes themselves.
nlohmann::json json_text(const std::string& bytes) {
  return nlohmann::json::parse(nlohmann::json(bytes).dump(-1, ' ', false, nlohmann::json::error_handler_t::replace));
}

nlohmann::json optional_number(const std::optional<double>& v) {
  return v ? nlohmann::json(*v) : nlohmann::json(nullptr);
}

std::string letter(int grade) { return std::string(1, grade_letter(grade)); }

}  // namespace

nlohmann::json iso_grade_json(const IsoGrade& g) {
  nlohmann::json segments = nlohmann::json::object();
  for (const SegmentGrade& s : g.segments)
    segments[s.name] = {{"grade", letter(s.grade)}, {"damaged_modules", s.damaged}, {"modules", s.modules}};
  return {{"standard", "ISO/IEC TR 29158"},
          {"overall", letter(g.overall)},
          {"decode", letter(g.decode)},
          {"cell_contrast", letter(g.cell_contrast_grade)},
          {"cell_contrast_fraction", g.cell_contrast},
          {"cell_modulation", letter(g.cell_modulation_grade)},
          {"cell_modulation_fraction", g.cell_modulation},
          {"fixed_pattern_damage", letter(g.fixed_pattern_grade)},
          {"fixed_pattern_average", g.fixed_pattern_average},
          {"fixed_pattern_segments", segments},
          {"axial_nonuniformity", letter(g.axial_nonuniformity_grade)},
          {"axial_nonuniformity_fraction", g.axial_nonuniformity},
          {"grid_nonuniformity", letter(g.grid_nonuniformity_grade)},
          {"grid_nonuniformity_modules", g.grid_nonuniformity},
          {"unused_error_correction", letter(g.unused_error_correction_grade)},
          {"unused_error_correction_fraction", g.unused_error_correction},
          {"codewords_wrong", g.codewords_wrong},
          {"print_growth_x_fraction", optional_number(g.print_growth_x)},
          {"print_growth_y_fraction", optional_number(g.print_growth_y)},
          {"mean_light_grey", g.mean_light},
          {"mean_dark_grey", g.mean_dark},
          {"global_threshold_grey", g.global_threshold},
          {"module_x_px", g.module_x_px},
          {"module_y_px", g.module_y_px},
          {"aperture_modules", g.aperture_modules}};
}

nlohmann::json code_to_json(const PlacedCode& code, const CodeSpec& spec, const CodeVerification& v) {
  nlohmann::json readers = nlohmann::json::array();
  for (const ReaderOutcome& r : v.readers)
    readers.push_back({{"reader", r.reader},
                       {"supported", r.supported},
                       {"decoded", r.decoded},
                       {"data_match", r.data_match}});
  nlohmann::json j = {
      {"symbology", std::string(to_string(spec.symbology))},
      {"data", json_text(spec.data)},
      {"rows", code.matrix.rows},
      {"cols", code.matrix.cols},
      {"module_um", v.module_um},
      {"width_mm", code.width_mm},
      {"height_mm", code.height_mm},
      {"quiet_zone_modules", code.quiet_modules},
      {"x_mm", code.layout.center.x()},
      {"y_mm", code.layout.center.y()},
      {"angle_deg", code.layout.angle_deg},
      {"style", std::string(to_string(code.layout.style))},
      {"inverted", code.layout.invert},
      {"hatch_lines", code.stats.hatch_lines},
      {"hatch_length_mm", code.stats.hatch_length_mm},
      {"reader", v.reader},
      {"decided_by", v.decided_by},
      {"readers", readers},
      {"decoded", v.decoded},
      {"decoded_data", json_text(v.decoded_data)},
      {"data_match", v.data_match},
      {"module_x_um", optional_number(v.module_x_um)},
      {"module_y_um", optional_number(v.module_y_um)},
      {"axial_nonuniformity_pct", optional_number(v.axial_nonuniformity_pct)},
      {"fill_ratio", optional_number(v.fill_ratio)},
      {"fill_ratio_min", optional_number(v.fill_ratio_min)},
      {"spill_ratio", optional_number(v.spill_ratio)},
      {"modules_wrong", v.modules_wrong},
      {"camera_px_um", v.camera_px_um},
      {"iso", v.grade ? iso_grade_json(*v.grade) : nlohmann::json(nullptr)}};
  return j;
}

}  // namespace mark

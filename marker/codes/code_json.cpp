#include "marker/codes/code_json.hpp"

namespace mark {
namespace {

// JSON strings must be UTF-8: bytes that are not (binary data) become U+FFFD; data_match
// compares the bytes themselves.
std::string json_text(const std::string& bytes) {
  return nlohmann::json(bytes).dump(-1, ' ', false, nlohmann::json::error_handler_t::replace);
}

nlohmann::json optional_number(const std::optional<double>& v) {
  return v ? nlohmann::json(*v) : nlohmann::json(nullptr);
}

}  // namespace

nlohmann::json code_to_json(const PlacedCode& code, const CodeSpec& spec, const CodeVerification& v) {
  nlohmann::json j = {
      {"symbology", std::string(to_string(spec.symbology))},
      {"data", nlohmann::json::parse(json_text(spec.data))},
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
      {"decoded", v.decoded},
      {"decoded_data", nlohmann::json::parse(json_text(v.decoded_data))},
      {"data_match", v.data_match},
      {"module_x_um", optional_number(v.module_x_um)},
      {"module_y_um", optional_number(v.module_y_um)},
      {"axial_nonuniformity_pct", optional_number(v.axial_nonuniformity_pct)},
      {"axial_nonuniformity_grade",
       v.axial_nonuniformity_pct ? nlohmann::json(std::string(1, axial_nonuniformity_grade(*v.axial_nonuniformity_pct)))
                                 : nlohmann::json(nullptr)},
      {"fill_ratio", v.fill_ratio},
      {"fill_ratio_min", v.fill_ratio_min},
      {"spill_ratio", v.spill_ratio},
      {"modules_wrong", v.modules_wrong},
      {"camera_px_um", v.camera_px_um}};
  return j;
}

}  // namespace mark

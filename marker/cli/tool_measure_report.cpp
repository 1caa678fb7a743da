#include "marker/cli/tool_measure_report.hpp"

#include <cstdio>

namespace mark::cli {

nlohmann::json tool_measurement_json(const ToolMeasurement& m, const ToolMeasureOptions& o) {
  nlohmann::json j = {{"diameter_mm", m.diameter_mm},
                      {"radius_mm", m.radius_mm},
                      {"center_x_mm", m.center_mm.x()},
                      {"center_y_mm", m.center_mm.y()},
                      {"center_x_px", m.circle_px.center.x()},
                      {"center_y_px", m.circle_px.center.y()},
                      {"radius_px", m.circle_px.radius},
                      {"pixel_size_um", o.pixel_size_um},
                      {"form_deviation_mm", m.form_deviation_mm},
                      {"form_deviation_angle_deg", m.form_deviation_angle_deg},
                      {"rms_mm", m.rms_mm},
                      {"edge_points", m.edge_points},
                      {"tangential_dropped", m.tangential_dropped},
                      {"tangential_angle_deg", o.tangential_angle_deg},
                      {"outliers", m.outliers}};
  if (o.nominal_diameter_mm) j["nominal_diameter_mm"] = *o.nominal_diameter_mm;
  if (m.size_deviation_mm) j["radius_deviation_mm"] = *m.size_deviation_mm;
  if (m.nominal_form_deviation_mm) j["nominal_form_deviation_mm"] = *m.nominal_form_deviation_mm;
  return j;
}

void print_tool_measurement(std::ostream& out, const ToolMeasurement& m, const ToolMeasureOptions& o) {
  char line[320];
  auto put = [&](const char* format, auto... values) {
    std::snprintf(line, sizeof line, format, values...);
    out << line;
  };
  put("diameter %.4f mm (radius %.4f mm)\n", m.diameter_mm, m.radius_mm);
  put("centre (%.4f, %.4f) mm from the image's top-left corner, x right, y down\n", m.center_mm.x(),
      m.center_mm.y());
  put("form deviation %.4f mm at %.1f° (%s), rms %.4f mm\n", m.form_deviation_mm, m.form_deviation_angle_deg,
      kAngleConvention, m.rms_mm);
  put("edge points %zu, tangential scans dropped %zu, defects left out of the fit %zu\n", m.edge_points,
      m.tangential_dropped, m.outliers);
  if (m.size_deviation_mm)
    put("against nominal %.4f mm: radius %+.4f mm, largest deviation from the nominal circle %.4f mm\n",
        *o.nominal_diameter_mm, *m.size_deviation_mm, *m.nominal_form_deviation_mm);
}

}  // namespace mark::cli

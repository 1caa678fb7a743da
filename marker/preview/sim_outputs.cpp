#include "marker/preview/sim_outputs.hpp"

#include <cstdio>

#include "marker/output/output_file.hpp"

namespace mark {

GreyImage dose_part_picture(const DoseRaster& dose, const MarkResponse& response, const PartLook& look,
                            bool dark_part) {
  FieldWindow window;
  if (!dosed_window(dose, 0.2, window)) window = {-1, -1, 1, 1};  // nothing dosed: a bare square
  return part_picture(dose, window, response, dark_part ? dark_part_look(look) : look);
}

void write_trace_csv(const std::vector<SimTraceRow>& rows, const std::string& path) {
  std::string csv = "t_s,cmd_x_mm,cmd_y_mm,laser,beam_x_mm,beam_y_mm\n";
  csv.reserve(csv.size() + rows.size() * 56);
  char line[160];
  for (const SimTraceRow& r : rows) {
    const int n = std::snprintf(line, sizeof line, "%.6f,%.5f,%.5f,%d,%.5f,%.5f\n", r.t_s, r.cmd_x_mm,
                                r.cmd_y_mm, r.laser ? 1 : 0, r.beam_x_mm, r.beam_y_mm);
    csv.append(line, static_cast<std::size_t>(n));
  }
  write_file_whole(path, csv);
}

}  // namespace mark

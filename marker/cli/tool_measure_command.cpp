// `marker tool-measure IMAGE --pixel-size UM [--nominal-diameter MM]`: the cutter's actual
// radius, centre and form deviation from a back-lit shadow image (US 5,255,199).
#include <cstdio>
#include <iostream>

#include "marker/cli/commands.hpp"
#include "marker/cnc/tool/tool_measure.hpp"

namespace mark::cli {

Command make_tool_measure_command() {
  struct Args {
    std::string image;
    ToolMeasureOptions options;
    double nominal_mm = 0;
  };
  auto a = std::make_shared<Args>();
  return Command(
      [a](CLI::App& app) {
        auto* sub = app.add_subcommand("tool-measure", "measure a cutter from a back-lit (shadow) image");
        sub->add_option("image", a->image, "PNG or PGM image of the tool seen along its axis")->required();
        sub->add_option("--pixel-size", a->options.pixel_size_um, "micrometres per pixel at the tool")->required();
        sub->add_option("--nominal-diameter", a->nominal_mm, "the diameter the toolpaths assume, mm");
        sub->add_option("--tangential-angle", a->options.tangential_angle_deg,
                        "scans more than this far from the edge normal are dropped, degrees")
            ->capture_default_str();
        return sub;
      },
      [a] {
        if (a->nominal_mm > 0) a->options.nominal_diameter_mm = a->nominal_mm;
        const ToolMeasurement m = measure_tool(read_gray_image(a->image), a->options, a->image);
        char line[256];
        std::snprintf(line, sizeof line, "diameter %.4f mm (radius %.4f mm)\n", m.diameter_mm, m.radius_mm);
        std::cout << line;
        std::snprintf(line, sizeof line, "centre (%.4f, %.4f) mm from the image's top-left corner\n",
                      m.center_mm.x(), m.center_mm.y());
        std::cout << line;
        std::snprintf(line, sizeof line, "form deviation %.4f mm at %.1f deg, rms %.4f mm\n", m.form_deviation_mm,
                      m.form_deviation_angle_deg, m.rms_mm);
        std::cout << line;
        std::snprintf(line, sizeof line, "edge points %zu, tangential scans dropped %zu, defects left out of the fit %zu\n",
                      m.edge_points, m.tangential_dropped, m.outliers);
        std::cout << line;
        if (m.size_deviation_mm) {
          std::snprintf(line, sizeof line,
                        "against nominal %.4f mm: radius %+.4f mm, largest deviation from the nominal circle %.4f mm\n",
                        *a->options.nominal_diameter_mm, *m.size_deviation_mm, *m.nominal_form_deviation_mm);
          std::cout << line;
        }
        return 0;
      });
}

}  // namespace mark::cli

// `marker tool-measure IMAGE --pixel-size UM [--nominal-diameter MM] [--tangential-angle DEG]
//  [--json]`: the cutter's actual radius, centre and form deviation from a back-lit shadow image
// (US 5,255,199).
#include <iostream>

#include "marker/cli/commands.hpp"
#include "marker/cli/option_ranges.hpp"
#include "marker/cli/tool_measure_report.hpp"
#include "marker/cnc/tool/tool_measure.hpp"
#include "marker/limits/cnc_settings.hpp"

namespace mark::cli {

Command make_tool_measure_command() {
  struct Args {
    std::string image;
    ToolMeasureOptions options;
    std::optional<double> nominal_mm;
    bool json = false;
  };
  auto a = std::make_shared<Args>();
  return Command(
      [a](CLI::App& app) {
        auto* sub = app.add_subcommand("tool-measure", "measure a cutter from a back-lit (shadow) image");
        sub->add_option("image", a->image, "PNG or PGM image of the tool seen along its axis")->required();
        add_setting(*sub, kPixelSize, a->options.pixel_size_um)->required();
        add_setting(*sub, kNominalDiameter, a->nominal_mm);
        add_setting(*sub, kTangentialAngle, a->options.tangential_angle_deg);
        sub->add_flag("--json", a->json, "print the measurement as one JSON object (docs/json.md)");
        return sub;
      },
      [a] {
        a->options.nominal_diameter_mm = a->nominal_mm;
        const ToolMeasurement m = measure_tool(read_gray_image(a->image), a->options, a->image);
        if (a->json) {
          nlohmann::json j = tool_measurement_json(m, a->options);
          j["image"] = a->image;
          std::cout << j.dump(2) << "\n";
        } else {
          print_tool_measurement(std::cout, m, a->options);
        }
        return 0;
      });
}

}  // namespace mark::cli

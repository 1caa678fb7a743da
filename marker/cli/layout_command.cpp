// `marker layout TEXT [layout options] --json`: the Figure for other tools.
#include <iostream>
#include <nlohmann/json.hpp>

#include "marker/cli/commands.hpp"
#include "marker/cli/layout_options.hpp"
#include "marker/layout/figure_json.hpp"

namespace mark::cli {

Command make_layout_command() {
  struct Args {
    std::string text;
    LayoutArgs layout;
    bool json = false;
  };
  auto a = std::make_shared<Args>();
  return Command(
      [a](CLI::App& app) {
        auto* sub = app.add_subcommand("layout", "lay the text out and print the figure");
        sub->add_option("text", a->text, "text to lay out (UTF-8)")->required();
        add_layout_options(*sub, a->layout);
        add_fill_options(*sub, a->layout);
        sub->add_flag("--json", a->json, "print the figure as JSON (elements in mm, field frame)");
        return sub;
      },
      [a] {
        const LaidOutText laid = build_figure(a->text, a->layout);
        if (a->json) {
          nlohmann::json j = figure_to_json(laid.figure);
          if (laid.fill)
            j["fill"] = {{"hatch_lines", laid.fill->hatch_lines},
                         {"hatch_length_mm", laid.fill->hatch_length_mm},
                         {"contour_loops", laid.fill->contour_loops},
                         {"contour_length_mm", laid.fill->contour_length_mm},
                         {"jump_length_mm", laid.fill->jump_length_mm},
                         {"area_mm2", laid.fill->area_mm2}};
          std::cout << j.dump() << "\n";
          return 0;
        }
        const Box b = laid.figure.bounds();
        std::cout << laid.figure.glyphs.size() << " glyphs, " << laid.figure.element_count()
                  << " elements, marked length " << laid.figure.mark_length_mm() << " mm\n"
                  << "bounds x " << b.min.x() << " .. " << b.max.x() << " mm, y " << b.min.y()
                  << " .. " << b.max.y() << " mm\n";
        if (laid.fill)
          std::cout << "fill: " << laid.fill->hatch_lines << " hatch lines (" << laid.fill->hatch_length_mm
                    << " mm), " << laid.fill->contour_loops << " contour loops, jumps "
                    << laid.fill->jump_length_mm << " mm, area " << laid.fill->area_mm2 << " mm²\n";
        return 0;
      });
}

}  // namespace mark::cli

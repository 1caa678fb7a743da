// `marker preview TEXT [layout options] -o FILE.svg|FILE.png [--no-travel] [--json] [--quiet]`
#include <iostream>
#include <nlohmann/json.hpp>

#include "marker/cli/commands.hpp"
#include "marker/cli/console_progress.hpp"
#include "marker/cli/layout_options.hpp"
#include "marker/cli/option_ranges.hpp"
#include "marker/cli/output_options.hpp"
#include "marker/layout/figure_json.hpp"
#include "marker/limits/marking_settings.hpp"
#include "marker/output/output_file.hpp"
#include "marker/preview/figure_preview.hpp"

namespace mark::cli {

Command make_preview_command() {
  struct Args {
    std::string text;
    LayoutArgs layout;
    std::string output;
    bool no_travel = false;
    bool json = false;
    bool quiet = false;
  };
  auto a = std::make_shared<Args>();
  return Command(
      [a](CLI::App& app) {
        auto* sub = app.add_subcommand("preview", "draw the laid-out text with the field frame (SVG or PNG)");
        sub->add_option("text", a->text, "text to lay out (UTF-8; \\n in the text starts a new line)")->required();
        add_layout_options(*sub, a->layout);
        add_fill_options(*sub, a->layout);
        sub->add_option("-o,--output", a->output, "output file, .svg or .png")->required();
        add_setting(*sub, kNoTravel, a->no_travel);
        sub->add_flag("--json", a->json, "print what was drawn as one JSON object (docs/json.md)");
        sub->add_flag("--quiet", a->quiet, "no progress lines on stderr");
        return sub;
      },
      [a] {
        check_standard_output({{"--output", &a->output}}, a->json);
        check_output_path("--output", a->output, {".svg", ".png"});
        ConsoleProgress progress = command_progress(a->quiet || a->json);
        const LaidOutText laid = build_figure(a->text, a->layout);
        PreviewOptions options;
        options.progress = &progress;
        options.show_travel = !a->no_travel;
        options.circle = to_layout_options(a->layout).circle;
        // The drawing stops at its own steps from here on; the file goes out whole at its end.
        progress.writing_files();
        write_figure_preview(laid.figure, laid.field, a->output, options);
        const Box b = laid.figure.bounds();
        if (a->json) {
          const nlohmann::json j = {{"output", a->output},
                                    {"text", unescape_text(a->text)},
                                    {"font", a->layout.font},
                                    {"height_mm", a->layout.height_mm},
                                    {"glyphs", laid.figure.glyphs.size()},
                                    {"elements", laid.figure.element_count()},
                                    {"mark_length_mm", laid.figure.mark_length_mm()},
                                    {"bounds_mm", box_json(b)},
                                    {"field_mm", laid.field.size_mm}};
          std::cout << j.dump(2) << "\n";
          return 0;
        }
        std::cerr << "marker: wrote " << a->output << " (" << laid.figure.glyphs.size() << " glyphs, "
                  << laid.figure.element_count() << " elements)\n";
        return 0;
      });
}

}  // namespace mark::cli

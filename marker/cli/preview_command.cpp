// `marker preview TEXT [layout options] -o FILE.svg|FILE.png`
#include <iostream>

#include "marker/cli/commands.hpp"
#include "marker/cli/layout_options.hpp"
#include "marker/preview/figure_preview.hpp"

namespace mark::cli {

Command make_preview_command() {
  struct Args {
    std::string text;
    LayoutArgs layout;
    std::string output;
    bool no_travel = false;
  };
  auto a = std::make_shared<Args>();
  return Command(
      [a](CLI::App& app) {
        auto* sub = app.add_subcommand("preview", "draw the laid-out text with the field frame (SVG or PNG)");
        sub->add_option("text", a->text, "text to lay out (UTF-8; \\n in the text starts a new line)")->required();
        add_layout_options(*sub, a->layout);
        add_fill_options(*sub, a->layout);
        sub->add_option("-o,--output", a->output, "output file, .svg or .png")->required();
        sub->add_flag("--no-travel", a->no_travel, "leave out the dashed travel between strokes");
        return sub;
      },
      [a] {
        const LaidOutText laid = build_figure(a->text, a->layout);
        PreviewOptions options;
        options.show_travel = !a->no_travel;
        write_figure_preview(laid.figure, laid.field, a->output, options);
        std::cerr << "marker: wrote " << a->output << " (" << laid.figure.glyphs.size()
                  << " glyphs, " << laid.figure.element_count() << " elements)\n";
        return 0;
      });
}

}  // namespace mark::cli

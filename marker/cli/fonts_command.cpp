// `marker fonts`: the built-in font and the font files found on this machine.
#include <iostream>

#include "fonts/catalog.hpp"
#include "marker/cli/commands.hpp"

namespace mark::cli {

Command make_fonts_command() {
  return Command(
      [](CLI::App& app) {
        return app.add_subcommand("fonts", "list the built-in font and the stroke-font files on this machine");
      },
      [] {
        const StrokeFont& builtin = builtin_font();
        std::cout << "builtin  (built-in marking font, " << builtin.size() << " glyphs, default)\n";
        const auto fonts = installed_fonts();
        for (const FontFile& f : fonts) std::cout << f.name << "  " << f.format << "  " << f.path << "\n";
        if (fonts.empty()) {
          std::cout << "(no font files found in:";
          for (const std::string& d : font_directories()) std::cout << " " << d;
          std::cout << ")\n";
        }
        return 0;
      });
}

}  // namespace mark::cli

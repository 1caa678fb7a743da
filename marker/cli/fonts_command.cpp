// `marker fonts [--json]`: the built-in font and the font files found on this machine.
#include <iostream>
#include <nlohmann/json.hpp>

#include "fonts/catalog.hpp"
#include "marker/cli/commands.hpp"

namespace mark::cli {

Command make_fonts_command() {
  auto json = std::make_shared<bool>(false);
  return Command(
      [json](CLI::App& app) {
        auto* sub = app.add_subcommand("fonts", "list the built-in font and the stroke-font files on this machine");
        sub->add_flag("--json", *json, "print the list as one JSON object (docs/json.md)");
        return sub;
      },
      [json] {
        const StrokeFont& builtin = builtin_font();
        const auto fonts = installed_fonts();
        const std::vector<std::string> dirs = font_directories();
        if (*json) {
          nlohmann::json list = nlohmann::json::array();
          list.push_back({{"name", kBuiltinFontName}, {"format", "builtin"}, {"path", nullptr},
                          {"glyphs", builtin.size()}, {"unique", true}});
          for (const FontFile& f : fonts)
            list.push_back({{"name", f.name}, {"format", f.format}, {"path", f.path},
                            {"unique", font_name_is_unique(f.name, fonts)}});
          std::cout << nlohmann::json{{"fonts", list}, {"directories", dirs}}.dump(2) << "\n";
          return 0;
        }
        std::cout << "builtin  (built-in marking font, " << builtin.size() << " glyphs, default)\n";
        for (const FontFile& f : fonts) {
          std::cout << f.name << "  " << f.format << "  " << f.path;
          // A name that several files share must be given with its extension or as a path.
          if (!font_name_is_unique(f.name, fonts))
            std::cout << "  (name it " << f.name << "." << f.format << ")";
          std::cout << "\n";
        }
        if (fonts.empty()) {
          std::cout << "(no font files found in:";
          for (const std::string& d : dirs) std::cout << " " << d;
          std::cout << ")\n";
        }
        return 0;
      });
}

}  // namespace mark::cli

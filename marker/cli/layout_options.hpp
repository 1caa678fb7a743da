#pragma once
// The layout options every command that takes text shares: --font, --height, --width-factor,
// --gap, --line-spacing, --align, --x/--y, --angle, --circle with --start-angle or
// --self-centred and --inside, --italic, --mirror, --field. Commands that mark or draw the text
// also take the fill options: --fill none|hatch, --fill-rule and the hatch options.
#include <CLI/CLI.hpp>
#include <memory>
#include <optional>
#include <string>

#include "fonts/stroke_font.hpp"
#include "marker/cli/hatch_options.hpp"
#include "marker/fill/fill.hpp"
#include "marker/layout/layout.hpp"

namespace mark::cli {

struct LayoutArgs {
  std::string font = "builtin";
  double height_mm = 5.0;
  double width_factor = 1.0;
  double gap_mm = 0.0;
  double line_spacing = 1.0;
  std::string align = "left";
  double x_mm = 0.0;
  double y_mm = 0.0;
  double angle_deg = 0.0;
  std::string circle;  // "CX,CY,R"
  std::optional<double> start_angle_deg;
  bool self_centred = false;
  bool inside = false;
  double italic_deg = 0.0;
  bool mirror = false;
  bool replace_missing = false;
  double field_mm = 110.0;
  // Filled outline fonts.
  std::string fill = "none";       // none | hatch
  std::string fill_rule = "nonzero";
  HatchArgs hatch;
};

void add_layout_options(CLI::App& app, LayoutArgs& args);
void add_fill_options(CLI::App& app, LayoutArgs& args);

// The fill to apply, or nothing for --fill none; insets default to `beam_radius_mm`. Throws
// InputError naming the option.
std::optional<FillOptions> to_fill(const LayoutArgs& args, double beam_radius_mm = 0.02);

// LayoutOptions from the parsed arguments; throws InputError for a malformed --circle.
LayoutOptions to_layout_options(const LayoutArgs& args);

struct LaidOutText {
  std::shared_ptr<const StrokeFont> font;
  Figure figure;
  Field field;
  std::optional<FillStats> fill;  // when the text was filled
};

// Command-line text: a backslash-n starts a new line, a double backslash is one backslash.
std::string unescape_text(const std::string& text);

// What to change when a text leaves the field, appended to the layout's message.
inline constexpr const char* kFieldRemedy =
    "lower --height, move the text with --x, --y or --align, or enlarge --field";

// Opens the font, lays the text out (and fills it with --fill hatch), and refuses an empty text
// or a layout that leaves the field.
LaidOutText build_figure(const std::string& text, const LayoutArgs& args);

}  // namespace mark::cli

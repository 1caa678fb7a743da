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
#include "marker/limits/head_settings.hpp"
#include "marker/limits/layout_settings.hpp"

namespace mark::cli {

struct LayoutArgs {
  // Defaults from the settings table (marker/limits/layout_settings.hpp).
  std::string font{kFont.value};
  double height_mm = *kHeight.value;
  double width_factor = *kWidthFactor.value;
  double gap_mm = *kGap.value;
  double line_spacing = *kLineSpacing.value;
  std::string align{kAlign.value};
  double x_mm = *kX.value;
  double y_mm = *kY.value;
  double angle_deg = *kAngle.value;
  std::string circle;  // "CX,CY,R"
  std::optional<double> start_angle_deg;
  bool self_centred = false;
  bool inside = false;
  double italic_deg = *kItalic.value;
  bool mirror = false;
  bool replace_missing = false;
  double field_mm = *kField.value;
  // Spacing as F-Engrave gives it (add_spacing_options): the gap after each letter's drawing and
  // the advance of a space, in % of the character height; unset: the font's own spacing.
  std::optional<double> char_spacing_pct;
  std::optional<double> word_spacing_pct;
  // Filled outline fonts.
  std::string fill{kFill.value};  // none | hatch
  std::string fill_rule{kFillRule.value};
  HatchArgs hatch;
};

// `font`: the font setting the command takes (peen's dot fonts have their own). `galvo_field`:
// the text is marked in a square galvo field (--field, --x/--y inside it); a milling machine has
// a stock and a travel instead, and its command checks those.
void add_layout_options(CLI::App& app, LayoutArgs& args, const Text& font = kFont, bool galvo_field = true);
// --char-spacing PCT, --word-spacing PCT (F-Engrave's spacing; the font's own without them).
void add_spacing_options(CLI::App& app, LayoutArgs& args);
void add_fill_options(CLI::App& app, LayoutArgs& args);

// The fill to apply, or nothing for --fill none; insets default to `beam_radius_mm`. Throws
// InputError naming the option.
std::optional<FillOptions> to_fill(const LayoutArgs& args, double beam_radius_mm = 0.02);

// LayoutOptions from the parsed arguments with --x/--y inside the --field; throws InputError for
// a malformed --circle.
LayoutOptions to_layout_options(const LayoutArgs& args);
// The same with --x/--y checked against the given range (a machine's travel).
LayoutOptions to_layout_options(const LayoutArgs& args, const Range& position);

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

// Opens the font (respaced by --char-spacing / --word-spacing), lays the text out (and fills it
// with --fill hatch), and refuses an empty text. No field: the caller checks where it lies.
LaidOutText lay_out_text(const std::string& text, const LayoutArgs& args, const LayoutOptions& options);

// lay_out_text with the options from the arguments, refusing a layout that leaves the field.
LaidOutText build_figure(const std::string& text, const LayoutArgs& args);

}  // namespace mark::cli

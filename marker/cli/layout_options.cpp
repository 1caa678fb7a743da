#include "marker/cli/layout_options.hpp"

#include <iostream>

#include "base/error.hpp"
#include "fonts/catalog.hpp"
#include "marker/cli/option_ranges.hpp"
#include "marker/cli/option_values.hpp"
#include "marker/layout/respace.hpp"
#include "marker/limits/layout_limits.hpp"

namespace mark::cli {
namespace {

CircleFit parse_circle(const LayoutArgs& args) {
  const std::string option = "--circle '" + args.circle + "'";
  const std::vector<double> v = parse_numbers("--circle", args.circle, ",", 3, "CX,CY,R in millimetres");
  check_range(option + " centre x", v[0], kPositionRange);
  check_range(option + " centre y", v[1], kPositionRange);
  check_range(option + " radius", v[2], kRadiusRange);
  CircleFit fit;
  fit.center = Point(v[0], v[1]);
  fit.radius_mm = v[2];
  fit.inside = args.inside;
  fit.start_angle_deg = args.start_angle_deg;
  return fit;
}

}  // namespace

std::string unescape_text(const std::string& text) {
  std::string out;
  out.reserve(text.size());
  for (std::size_t i = 0; i < text.size(); ++i) {
    if (text[i] == '\\' && i + 1 < text.size() && (text[i + 1] == 'n' || text[i + 1] == '\\')) {
      out += text[i + 1] == 'n' ? '\n' : '\\';
      ++i;
    } else {
      out += text[i];
    }
  }
  return out;
}

void add_layout_options(CLI::App& app, LayoutArgs& a, bool galvo_field) {
  app.add_option("--font", a.font, "font: 'builtin', an installed font name (see 'marker fonts') or a .jhf/.lff/.cxf file")
      ->capture_default_str();
  add_ranged_option(app, "--height", a.height_mm, "character (cap) height, mm", kHeightRange)
      ->capture_default_str();
  add_ranged_option(app, "--width-factor", a.width_factor, "horizontal scale of the letters", kWidthFactorRange)
      ->capture_default_str();
  add_ranged_option(app, "--gap", a.gap_mm, "extra gap between letters, mm (at least -height/2)", kGapRange)
      ->capture_default_str();
  add_ranged_option(app, "--line-spacing", a.line_spacing, "factor on the font's line height", kLineSpacingRange)
      ->capture_default_str();
  app.add_option("--align", a.align, "alignment of each line about the base point")
      ->check(CLI::IsMember({"left", "center", "right"}))
      ->capture_default_str();
  const std::string frame = galvo_field ? "field frame, mm; inside the field" : "work coordinates, mm; inside the --travel";
  add_ranged_option(app, "--x", a.x_mm, "base point x (" + frame + ")", kPositionRange)->capture_default_str();
  add_ranged_option(app, "--y", a.y_mm, "base point y (first baseline; " + frame + ")", kPositionRange)
      ->capture_default_str();
  add_ranged_option(app, "--angle", a.angle_deg, "inclined fitting: rotate the text about the base point, degrees",
                    kAngleRange)
      ->capture_default_str();
  auto* circle = app.add_option("--circle", a.circle,
                                "circular fitting around CX,CY with radius R (mm; CX, CY " +
                                    kPositionRange.text() + ", R " + kRadiusRange.text() + ")");
  auto* start = add_ranged_option(app, "--start-angle", a.start_angle_deg,
                                  "circular fitting: angle where the text starts, degrees", kAngleRange);
  auto* centred = app.add_flag("--self-centred,--self-centered", a.self_centred,
                               "circular fitting: centre the text on the top (bottom with --inside) of the circle (default)");
  auto* inside = app.add_flag("--inside", a.inside, "circular fitting: letters inside the circle, reading along its bottom");
  start->needs(circle);
  centred->needs(circle);
  inside->needs(circle);
  start->excludes(centred);
  add_ranged_option(app, "--italic", a.italic_deg, "font inclination (shear), degrees", kItalicRange)
      ->capture_default_str();
  app.add_flag("--mirror", a.mirror, "mirror the text (reverse the letter order, mirror each letter)");
  app.add_flag("--replace-missing", a.replace_missing, "draw the font's replacement glyph for characters it lacks");
  if (galvo_field)
    add_ranged_option(app, "--field", a.field_mm, "field size (square), mm", kFieldRange)->capture_default_str();
}

void add_spacing_options(CLI::App& app, LayoutArgs& a) {
  add_ranged_option(app, "--char-spacing", a.char_spacing_pct,
                    "gap after each letter's drawing, % of the character height (F-Engrave's character "
                    "spacing; default: the font's own)",
                    kCharSpacingRange);
  add_ranged_option(app, "--word-spacing", a.word_spacing_pct,
                    "advance of a space, % of the character height (default: the font's own)", kWordSpacingRange);
}

void add_fill_options(CLI::App& app, LayoutArgs& a) {
  app.add_option("--fill", a.fill, "fill outline-font letters: none, hatch")->capture_default_str();
  app.add_option("--fill-rule", a.fill_rule, "inside of overlapping outlines: nonzero (TrueType, CFF), evenodd")
      ->capture_default_str();
  add_hatch_options(app, a.hatch);
}

std::optional<FillOptions> to_fill(const LayoutArgs& a, double beam_radius_mm) {
  if (a.fill == "none") return std::nullopt;
  if (a.fill != "hatch") throw InputError("--fill '" + a.fill + "' is not one of none, hatch");
  FillOptions o = to_fill_options(a.hatch, beam_radius_mm);
  o.rule = parse_fill_rule(a.fill_rule);
  return o;
}

LayoutOptions to_layout_options(const LayoutArgs& a) {
  // The base point lies in the field the text is checked against.
  return to_layout_options(a, Range{-a.field_mm / 2, a.field_mm / 2, "mm (the --field is " + format_number(a.field_mm) + " mm)"});
}

LayoutOptions to_layout_options(const LayoutArgs& a, const Range& position) {
  check_range("--x", a.x_mm, position);
  check_range("--y", a.y_mm, position);
  LayoutOptions o;
  o.height_mm = a.height_mm;
  o.width_factor = a.width_factor;
  o.gap_mm = a.gap_mm;
  o.line_spacing = a.line_spacing;
  o.align = a.align == "center" ? Align::center : a.align == "right" ? Align::right : Align::left;
  o.base = Point(a.x_mm, a.y_mm);
  o.angle_deg = a.angle_deg;
  if (!a.circle.empty()) o.circle = parse_circle(a);
  o.italic_deg = a.italic_deg;
  o.mirror = a.mirror;
  o.replace_missing = a.replace_missing;
  return o;
}

LaidOutText lay_out_text(const std::string& text, const LayoutArgs& args, const LayoutOptions& options) {
  Warnings warnings;
  LaidOutText out;
  out.font = open_font(args.font, &warnings);
  for (const std::string& w : warnings) std::cerr << "marker: warning: " << w << "\n";
  if (args.char_spacing_pct || args.word_spacing_pct)
    out.font = std::make_shared<const StrokeFont>(respaced_font(*out.font, args.char_spacing_pct, args.word_spacing_pct));
  const std::optional<FillOptions> fill = to_fill(args);
  out.figure = layout_text(unescape_text(text), *out.font, options);
  if (fill) {
    FillStats stats;
    out.figure = fill_figure(out.figure, *fill, &stats);
    out.fill = stats;
  }
  out.field = Field{args.field_mm};
  if (out.figure.bounds().empty()) throw InputError("text '" + text + "' has nothing to mark");
  return out;
}

LaidOutText build_figure(const std::string& text, const LayoutArgs& args) {
  LaidOutText out = lay_out_text(text, args, to_layout_options(args));
  require_inside(out.figure.bounds(), out.field, "the text layout", kFieldRemedy);
  return out;
}

}  // namespace mark::cli

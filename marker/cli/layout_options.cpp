#include "marker/cli/layout_options.hpp"

#include <iostream>

#include "base/error.hpp"
#include "fonts/catalog.hpp"
#include "marker/cli/option_ranges.hpp"
#include "marker/cli/option_values.hpp"
#include "marker/layout/respace.hpp"
#include "marker/limits/head_settings.hpp"
#include "marker/limits/layout_settings.hpp"

namespace mark::cli {
namespace {

CircleFit parse_circle(const LayoutArgs& args) {
  const std::string option = "--circle '" + args.circle + "'";
  const std::vector<double> v = parse_numbers("--circle", args.circle, ",", 3, "CX,CY,R in millimetres");
  check_range(option + " centre x", v[0], kCircleX.range());
  check_range(option + " centre y", v[1], kCircleY.range());
  check_range(option + " radius", v[2], kCircleRadius.range());
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

void add_layout_options(CLI::App& app, LayoutArgs& a, const Text& font, bool galvo_field) {
  add_setting(app, font, a.font);
  add_setting(app, kHeight, a.height_mm);
  add_setting(app, kWidthFactor, a.width_factor);
  add_setting(app, kGap, a.gap_mm);
  add_setting(app, kLineSpacing, a.line_spacing);
  add_setting(app, kAlign, a.align);
  add_setting(app, galvo_field ? kX : kWorkX, a.x_mm);
  add_setting(app, galvo_field ? kY : kWorkY, a.y_mm);
  add_setting(app, kAngle, a.angle_deg);
  auto* circle = add_setting(app, kCircle, a.circle);
  auto* start = add_setting(app, kStartAngle, a.start_angle_deg);
  auto* centred = add_setting(app, kSelfCentred, a.self_centred);
  auto* inside = add_setting(app, kInside, a.inside);
  start->needs(circle);
  centred->needs(circle);
  inside->needs(circle);
  start->excludes(centred);
  add_setting(app, kItalic, a.italic_deg);
  add_setting(app, kMirror, a.mirror);
  add_setting(app, kReplaceMissing, a.replace_missing);
  if (galvo_field) add_setting(app, kField, a.field_mm);
}

void add_spacing_options(CLI::App& app, LayoutArgs& a) {
  add_setting(app, kCharSpacing, a.char_spacing_pct);
  add_setting(app, kWordSpacing, a.word_spacing_pct);
}

void add_fill_options(CLI::App& app, LayoutArgs& a) {
  add_setting(app, kFill, a.fill);
  add_setting(app, kFillRule, a.fill_rule);
  add_hatch_options(app, a.hatch);
}

std::optional<FillOptions> to_fill(const LayoutArgs& a, double beam_radius_mm) {
  if (a.fill == "none") return std::nullopt;
  if (!kFill.allows(a.fill)) throw InputError("--fill '" + a.fill + "' is not one of " + std::string(kFill.choices));
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

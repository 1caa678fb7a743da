#pragma once
// Text layout: text (UTF-8, several lines) + font + fitting → Figure. Follows the CNC paper's data
// processor (scaling to height, letter gap, linear / inclined / circular fitting, font inclination
// by shear, mirroring), with Eigen affine transforms.
#include <cstdint>
#include <optional>
#include <string_view>

#include "fonts/stroke_font.hpp"
#include "marker/layout/figure.hpp"

namespace mark {

enum class Align { left, center, right };

// Circular fitting around a centre. Letters stand on the circle (baseline on it); outside: tops
// away from the centre, reading clockwise; inside: tops toward the centre, reading
// counter-clockwise (text at the bottom of a seal).
struct CircleFit {
  Point center{0, 0};
  double radius_mm = 0;
  // Angle (degrees, from +x counter-clockwise) where the first letter starts. Unset means
  // self-centred: θs = 90° + θt/2 outside (270° − θt/2 inside), θt = S_T / R,
  // S_T = ΣW + (n−1)G.
  std::optional<double> start_angle_deg;
  bool inside = false;
};

struct LayoutOptions {
  double height_mm = 5.0;     // cap height of the letters
  double width_factor = 1.0;  // horizontal scale relative to the height
  double gap_mm = 0.0;        // extra gap G between letters
  double line_spacing = 1.0;  // factor on the font's line height
  Align align = Align::left;
  Point base{0, 0};           // base point: left / centre / right end of the first baseline
  double angle_deg = 0.0;     // inclined fitting: rotation of the whole text about the base point
  std::optional<CircleFit> circle;
  double italic_deg = 0.0;    // font inclination: shear x' = x + y·tan(italic)
  bool mirror = false;        // reverse the letter order and mirror each letter
  bool replace_missing = false;  // use the font's replacement glyph instead of failing
};

// Throws InputError for an impossible parameter (non-positive height, width factor or radius,
// text too long for its circle) and MissingGlyphError for a character the font lacks.
Figure layout_text(std::string_view utf8_text, const StrokeFont& font, const LayoutOptions& options);
// Lays `utf8_text` out again into `figure`, which holds an earlier layout with the same font and
// options (or nothing): characters already shaped are not shaped again, and glyphs that keep
// their character and place keep their elements — only what changed is transformed. The result
// equals layout_text()'s. Same errors; on an error `figure` is left empty of glyphs.
void relayout_text(std::string_view utf8_text, const StrokeFont& font, const LayoutOptions& options,
                   Figure& figure);
// Texts this process has laid out (layout_text and relayout_text calls): tests and benchmarks
// hold a command to one layout per mark with it.
std::uint64_t layouts_made();

// A square field centred on the origin.
struct Field {
  double size_mm = 110.0;
  Box box() const {
    Box b;
    b.add(Point(-size_mm / 2, -size_mm / 2));
    b.add(Point(size_mm / 2, size_mm / 2));
    return b;
  }
};

// Throws InputError naming what leaves the field, on which side and by how much, and where it
// lies; `remedy` (what the user can change) ends the message when given.
void require_inside(const Box& bounds, const Field& field, std::string_view what,
                    std::string_view remedy = {});

}  // namespace mark

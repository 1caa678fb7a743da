#pragma once
// A code's modules as marks in the field. Three styles, as laser DPM practice has them:
//   square — the dark modules unioned into one area and hatch-filled (marker/fill), lines fitted
//            to the module pitch so each row of modules gets the same number of lines;
//   dot    — a dot per module: a circle, or a spiral filling the disc (the dot-peen look), made
//            of exact semicircle arcs;
//   line   — one line through each row of modules, for modules about one beam diameter wide.
// Every mark ends a beam radius (the fill inset) inside its module, so the burnt area, not the
// beam's centre line, has the module's size. The quiet zone is kept clear (and is marked, with
// the light modules, when the code is inverted for a part whose marks turn light).
#include <optional>
#include <vector>

#include "fonts/element.hpp"
#include "marker/codes/code_spec.hpp"
#include "marker/codes/module_matrix.hpp"
#include "marker/fill/fill.hpp"
#include "marker/layout/figure.hpp"

namespace mark {

enum class ModuleStyle { square, dot, line };
enum class DotShape { spiral, circle };

std::string_view to_string(ModuleStyle style);
ModuleStyle parse_module_style(std::string_view name);  // square, dot, line
std::string_view to_string(DotShape shape);
DotShape parse_dot_shape(std::string_view name);  // spiral, circle

struct CodeLayout {
  Point center{0, 0};     // centre of the symbol (quiet zone not included), field mm
  double angle_deg = 0;   // the symbol turned counter-clockwise about its centre
  // Module size, or the symbol's width (quiet zone not included) from which it follows; give
  // one. Neither: kDefaultModule_mm.
  double module_mm = 0;
  double size_mm = 0;
  double bar_height_mm = 0;  // linear codes; 0: 15 % of the width, at least 5 modules
  ModuleStyle style = ModuleStyle::square;
  DotShape dot = DotShape::spiral;
  double dot_share = 1.0;  // dot diameter (outer edge of the burn) as a share of the module
  bool invert = false;     // mark the light modules and the quiet zone instead
  // Hatch of square modules (spacing; angle from the code's rows, or from the bars of a linear
  // code; direction; contour passes);
  // its inset is the beam radius every style keeps inside its module, its spacing the spiral's
  // pitch.
  FillOptions fill;
};

inline constexpr double kDefaultModule_mm = 0.25;

struct PlacedCode {
  ModuleMatrix matrix;
  CodeLayout layout;
  double module_mm = 0;
  double width_mm = 0;    // symbol without quiet zone
  double height_mm = 0;
  int quiet_modules = 0;
  Affine to_field = Affine::Identity();  // code frame (lower-left corner of the symbol at 0, y up) → field
  Box bounds;             // field bounds of the symbol with its quiet zone
  std::vector<Element> elements;  // the marks in drawing order, laser-off moves between them
  FillStats stats;        // hatch and jump figures of the marks
  CodeSpec spec;          // what it encodes (place_encoded; place_code leaves it empty)

  // Rectangle of module (row, col) in the code frame (row 0 at the top; negative or beyond the
  // symbol for quiet-zone modules).
  Box module_box(int row, int col) const;
  // Does a field point lie on the symbol or in its quiet zone (other marks must stay out)?
  bool keeps_clear(const Point& field) const;
  // The first point of the lit elements (sampled every 0.05 mm) that falls on the symbol or its
  // quiet zone, if any.
  std::optional<Point> first_intrusion(const std::vector<Element>& elements) const;
};

// Throws InputError for a layout outside its ranges, or modules too small for the beam and style.
PlacedCode place_code(const ModuleMatrix& matrix, const CodeLayout& layout);

// The code's marks as a figure of one glyph, for the planner and the previews.
Figure code_figure(const PlacedCode& code);

}  // namespace mark

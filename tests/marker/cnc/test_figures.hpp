#pragma once
// Test support: Figures built by hand from a few letters with lines, arcs and closed loops (the
// paper's "D" among them), fitted linearly, inclined or on a circle, optionally mirrored
// (reversed order, each letter mirrored, as the paper does) and sheared (italic → elliptical
// arcs). Shapes hold each distinct letter's local elements, placed glyphs origin + rotation +
// field elements, exactly like layout_text's Figures.
#include <string>

#include "marker/layout/figure.hpp"

namespace mark::test {

enum class Fit { linear, inclined, circular };

struct FigureSpec {
  std::string text = "DOLT";  // letters from: D O L T S E (anything else is a space)
  double height_mm = 6;
  double gap_mm = 1;
  Fit fit = Fit::linear;
  double angle_deg = 20;      // inclined fitting
  double radius_mm = 20;      // circular fitting
  bool mirror = false;
  double italic_deg = 0;      // shear
  Point base{-10, -2};
};

Figure make_figure(const FigureSpec& spec);

}  // namespace mark::test

#pragma once
// Fonts and shapes the fill tests share: DejaVu Sans and Liberation Sans from Debian
// (fonts-dejavu-core, fonts-liberation2), loaded once; one letter laid out as closed contours.
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "fonts/catalog.hpp"
#include "fonts/stroke_font.hpp"
#include "marker/fill/contours.hpp"
#include "marker/layout/layout.hpp"

namespace mark::test {

inline const std::string kDejaVuSans = "/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf";
inline const std::string kLiberationSans = "/usr/share/fonts/truetype/liberation2/LiberationSans-Regular.ttf";

inline const StrokeFont& outline_font(const std::string& path) {
  static std::map<std::string, std::shared_ptr<const StrokeFont>> cache;
  auto& f = cache[path];
  if (!f) f = open_font(path);
  return *f;
}

inline Box box(double x0, double y0, double x1, double y1) {
  Box b;
  b.add(Point(x0, y0));
  b.add(Point(x1, y1));
  return b;
}

// The letter's contours at the given cap height, origin at (x, 0).
inline std::vector<Contour> letter_contours(const std::string& font_path, const std::string& letter,
                                            double height_mm, double x_mm = 0) {
  LayoutOptions o;
  o.height_mm = height_mm;
  o.base = Point(x_mm, 0);
  const Figure f = layout_text(letter, outline_font(font_path), o);
  std::vector<Contour> out;
  for (const PlacedGlyph& g : f.glyphs) {
    std::vector<Contour> c = closed_contours(g.elements, letter);
    out.insert(out.end(), c.begin(), c.end());
  }
  return out;
}

}  // namespace mark::test

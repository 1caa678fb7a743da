#include "marker/layout/figure.hpp"

#include <Eigen/Geometry>

#include "fonts/stroke_join.hpp"

namespace mark {

Affine PlacedGlyph::placement() const {
  Affine a = Affine::Identity();
  a.translate(origin);
  a.rotate(rotation_rad);
  return a;
}

Box Figure::bounds() const {
  Box b;
  for (const PlacedGlyph& g : glyphs)
    for (const Element& e : g.elements)
      if (e.laser()) b.add(e.bounds());
  return b;
}

double Figure::join_tolerance_mm() const {
  return join_tolerance(letter_height_mm > 0 ? letter_height_mm : bounds().height());
}

std::size_t Figure::element_count() const {
  std::size_t n = 0;
  for (const PlacedGlyph& g : glyphs) n += g.elements.size();
  return n;
}

double Figure::mark_length_mm() const {
  double len = 0;
  for (const PlacedGlyph& g : glyphs)
    for (const Element& e : g.elements)
      if (e.laser()) len += e.length();
  return len;
}

}  // namespace mark

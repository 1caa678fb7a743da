#pragma once
// Dots to strike, after layout: every dot in the field frame (mm, origin at the field centre, y up)
// with the character it belongs to and its cell in that character's dot matrix (what the patent's
// block snake walks). This is what every dot-peen planner consumes.
#include <cstddef>
#include <vector>

#include "fonts/element.hpp"
#include "marker/peen/dot_font.hpp"

namespace mark {

struct Dot {
  Point pos_mm{0, 0};
  std::size_t character = 0;  // index of the marked character (those with dots), in text order
  DotCell cell;               // column from the left, row from the top, as the character is seen
};

struct DotText {
  std::vector<Dot> dots;
  std::size_t characters = 0;  // characters that carry at least one dot
  double pitch_mm = 0;         // distance between neighbouring rows of dots (the snakes' row step)
  // Per character: cell (col, row) → field mm of the cell's centre. The block snake needs it for
  // the cells its track passes without a dot (the corner after a step down).
  std::vector<Affine> cell_frames;

  Point cell_position(std::size_t character, const DotCell& c) const {
    return cell_frames.at(character) * Point(c.col, c.row);
  }

  Box bounds() const {
    Box b;
    for (const Dot& d : dots) b.add(d.pos_mm);
    return b;
  }
};

}  // namespace mark

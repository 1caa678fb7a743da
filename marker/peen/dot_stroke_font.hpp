#pragma once
// A dot-matrix font seen as a stroke font, so the text layout (height, spacing, inclined, circular,
// mirrored fitting) places dot characters with exactly the rules it uses for stroke characters.
// Every dot becomes one lit zero-length line at the dot's centre; the layout maps it like any
// other element and its start point is where the needle strikes.
#include "fonts/stroke_font.hpp"
#include "marker/peen/dot_font.hpp"

namespace mark {

// Font units are dot pitches. Column c of row r (from the top) sits at (c, rows − 1 − r): the bottom
// row is on the baseline and the character height (cap height, standard height) is rows − 1, the
// distance between the centres of the top and bottom rows. Advance: columns + 1 (one empty column
// between characters).
StrokeFont as_stroke_font(const DotFont& font);

}  // namespace mark

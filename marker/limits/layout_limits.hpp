#pragma once
// What a text's layout accepts, wherever it is given (the layout options of every command, a job
// file's objects). The largest field is a 10 m CNC table, the smallest a 1 mm micro-marking
// field; positions and radii stay within the largest field (the layout then checks the text
// against the field it is marked in).
#include "marker/limits/value_range.hpp"

namespace mark {

inline const Range kFieldRange = length_range(1, 10000);
inline const Range kPositionRange = length_range(-10000, 10000);
inline const Range kRadiusRange = positive_up_to(10000, "mm");
// 10 µm letters are below any laser spot; 10 m letters fill the largest field.
inline const Range kHeightRange = length_range(0.01, 10000);
inline const Range kWidthFactorRange{0.05, 20, ""};
// Letters that step backwards are refused by the layout (the gap must exceed −advance).
inline const Range kGapRange = length_range(-10000, 10000);
// Below half the font's line height, lines print over each other.
inline const Range kLineSpacingRange{0.5, 20, ""};
inline const Range kAngleRange{-360, 360, "degrees"};
// F-Engrave's spacing, in % of the character height: letters may overlap by up to half the
// height, or stand ten heights apart; a space from nothing to ten heights.
inline const Range kCharSpacingRange{-50, 1000, "% of the character height"};
inline const Range kWordSpacingRange{0, 1000, "% of the character height"};
// Beyond ±75° the shear slants a letter more than 3.7 times its height sideways.
inline const Range kItalicRange{-75, 75, "degrees"};

}  // namespace mark

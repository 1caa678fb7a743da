#pragma once
// Connecting the dots of a dot-marked symbol before it is read and graded, as ISO/IEC TR 29158
// does for dot-peened and laser-dotted symbols: a grey-level morphological closing of the marks
// (dilate, then erode, over a disc) bridges the gaps between neighbouring dots without filling
// the light modules, which are wider than the disc.
#include "base/grey_image.hpp"

namespace mark {

// `dark_marks`: the marks are darker than the part (else lighter: a dark part). A diameter
// below one pixel leaves the picture as it is.
GreyImage close_marks(const GreyImage& picture, double diameter_px, bool dark_marks);

}  // namespace mark

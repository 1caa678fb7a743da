#pragma once
// A picture turned into the code's own frame: the code's known angle undone, so its rows run
// along the picture's rows. Readers that scan along rows and columns (ZBar's linear decoders)
// see the bars upright at any angle the code was marked at.
#include "base/grey_image.hpp"
#include "marker/codes/code_marks.hpp"

namespace mark {

// The symbol with its quiet zone and `margin_mm` around it, resampled (bilinear) at the
// picture's pixel in the code's frame (row 0 at the top of the symbol). Its x0_mm / top_mm are
// in the code's frame (the symbol's lower-left corner at 0, 0), not the field's.
GreyImage code_frame_view(const GreyImage& picture, const PlacedCode& code, double margin_mm);

}  // namespace mark

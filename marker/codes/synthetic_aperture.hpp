#pragma once
// The synthetic aperture of a verifier (ISO/IEC 15415 and ISO/IEC TR 29158): every pixel of the
// reference image is the mean over a disc of the given diameter around it, so a verifier sees a
// symbol the way a reader's optics of that resolution would — gaps between dots or lines much
// narrower than the aperture close, specks vanish. TR 29158 sizes the aperture at 50 %–80 % of
// the module.
#include "base/grey_image.hpp"

namespace mark {

GreyImage synthetic_aperture(const GreyImage& image, double diameter_px);

}  // namespace mark

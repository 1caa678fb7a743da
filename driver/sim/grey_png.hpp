#pragma once
// Encodes a camera image as an 8-bit greyscale PNG with its pixel size in the pHYs chunk (pixels
// per metre), so a reader, a verifier or any scale-aware tool takes the picture at its true
// size. libpng directly: cairo cannot write pHYs. Like encode_dose_png it returns the file's
// bytes; the command line writes them whole (marker/output/output_file.hpp).
#include <string>

#include "base/grey_image.hpp"

namespace mark {

// Pixels per metre as the PNG stores them (rounded to a whole number).
unsigned pixels_per_metre(double pixel_mm);

// Throws std::runtime_error when the image is empty or has no pixel size.
std::string encode_grey_png(const GreyImage& image);

}  // namespace mark

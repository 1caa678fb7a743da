#pragma once
// Writes a camera image as an 8-bit greyscale PNG with its pixel size in the pHYs chunk (pixels
// per metre), so a reader, a verifier or any scale-aware tool takes the picture at its true
// size. libpng directly: cairo cannot write pHYs. The file is written under a temporary name and
// renamed, so a failure never leaves half a picture.
#include <string>

#include "driver/part_image.hpp"

namespace mark {

// Pixels per metre as the PNG stores them (rounded to a whole number).
unsigned pixels_per_metre(double pixel_mm);

// Throws std::runtime_error naming the file when it cannot be written.
void write_grey_png(const CameraImage& image, const std::string& path);

}  // namespace mark

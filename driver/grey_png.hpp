#pragma once
// Writes a camera image as an 8-bit greyscale PNG with its pixel size in the pHYs chunk (pixels
// per metre), so a reader, a verifier or any scale-aware tool takes the picture at its true
// size. libpng directly: cairo cannot write pHYs. Like the other picture writers it writes the
// path it is given; the command line writes to a temporary name and renames (cli/output_file).
#include <string>

#include "driver/part_image.hpp"

namespace mark {

// Pixels per metre as the PNG stores them (rounded to a whole number).
unsigned pixels_per_metre(double pixel_mm);

// Throws std::runtime_error naming the file when it cannot be written.
void write_grey_png(const CameraImage& image, const std::string& path);

}  // namespace mark

#pragma once
// Writes a dose raster as a greyscale PNG (cairo): dark = high dose on a white background, the
// used area plus a margin, y up.
#include <string>

#include "driver/sim/dose_raster.hpp"

namespace mark {

struct DosePngOptions {
  int margin_px = 8;
  int max_side_px = 4096;  // larger rasters are downsampled (max over each block) to fit
};

// The PNG file's bytes (the command line writes them through marker/output/output_file.hpp:
// checked before the job, written whole); throws DeviceError when the image cannot be made.
std::string encode_dose_png(const DoseRaster& dose, DosePngOptions options = {});

}  // namespace mark

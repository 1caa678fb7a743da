#pragma once
// Writes a dose raster as a greyscale PNG (cairo): dark = high dose on a white background, the
// used area plus a margin, y up. Throws DeviceError if the file cannot be written.
#include <string>

#include "driver/dose_raster.hpp"

namespace mark {

struct DosePngOptions {
  int margin_px = 8;
  int max_side_px = 4096;  // larger rasters are downsampled (max over each block) to fit
};

void write_dose_png(const DoseRaster& dose, const std::string& path, DosePngOptions options = {});

}  // namespace mark

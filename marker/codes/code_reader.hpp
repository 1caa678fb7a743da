#pragma once
// Readers for the camera image of a simulated mark: libdmtx for Data Matrix, ZBar for QR and
// Code 128 — real decoders, so "decodes" means what it means on the line. Each returns the
// decoded bytes and where the reader found the symbol, in camera pixels.
#include <array>
#include <optional>
#include <string>

#include "driver/sim/part_image.hpp"
#include "marker/codes/symbology.hpp"

namespace mark {

struct ReadResult {
  std::string reader;  // "libdmtx" or "zbar"
  bool decoded = false;
  std::string data;    // bytes as the reader returns them (GS1: element string, GS separators)
  // The symbol's extent the reader measured, in camera pixels: module pitch along the symbol's
  // rows (x) and columns (y); y is 0 for a linear code.
  double module_x_px = 0;
  double module_y_px = 0;
};

// Dark modules must be dark in the image.
ReadResult read_datamatrix(const CameraImage& image, int rows, int cols);
ReadResult read_with_zbar(const CameraImage& image, Symbology symbology, int rows, int cols);

// The reader for the symbology.
ReadResult read_code(const CameraImage& image, Symbology symbology, int rows, int cols);

}  // namespace mark

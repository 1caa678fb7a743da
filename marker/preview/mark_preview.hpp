#pragma once
// Preview of a simulated mark (`marker mark --preview`): the dose the simulated beam left, as a
// greyscale image (dark = more dose), under the planned path — blanking run-ins and run-outs
// blue, their joining lines and the jumps dashed, delay dwells as red dots — so the picture
// shows both what was commanded and what it burned. PNG or SVG by the file's extension.
#include <string>

#include "driver/sim/dose_raster.hpp"
#include "marker/plan/plan.hpp"

namespace mark {

// Throws InputError naming the file if it cannot be written.
void write_mark_preview(const Plan& plan, const DoseRaster& dose, const std::string& path);
// The same picture encoded, for an answer rather than a file: `format` is a name ending in .png
// or .svg ("preview.png").
std::string encode_mark_preview(const Plan& plan, const DoseRaster& dose, const std::string& format);

}  // namespace mark

#pragma once
// The lag test pattern marked on the simulated head — the plant as it is, which the fit is not
// told — and photographed as a flatbed scan or a camera over the whole pattern would take it:
// what `marker head test-pattern` gives on the simulator (and behind the emulated board), and the picture `marker head identify
// --from-image` fits.
#include "base/grey_image.hpp"
#include "driver/sim/camera_model.hpp"
#include "driver/sim/sim_scanner.hpp"
#include "marker/head/lag_fit.hpp"
#include "marker/head/lag_pattern.hpp"

namespace mark {

// The picture's pixel on the part unless the camera states one: 10 µm, a 2540 dpi scan.
inline constexpr double kLagPhotoPixelUm = 10;

// Marks the pattern (its samples at the head's tick, the laser at full power for the fastest
// line and the material marking one spot wide there) and photographs the pattern's extent plus
// 1.5 mm, the camera's sensor grown to hold it. Throws DeviceFaultError when the plant's drive
// trips, std::invalid_argument for camera settings outside their ranges.
GreyImage photograph_lag_pattern(const SimScannerOptions& head, const LagPattern& pattern,
                                 CameraSettings camera = {});

// The photograph alone, of a pattern already marked into `dose` (by the emulated board's
// scanner, say), with the same material and camera.
GreyImage photograph_lag_dose(const DoseRaster& dose, const LagPattern& pattern, CameraSettings camera = {});

// The whole identification from a picture on the simulator, as a user runs it with the two
// commands: the head's pattern marked on the plant as it is, photographed, and fitted.
LagFit photographed_lag_fit(const SimScannerOptions& head);

}  // namespace mark

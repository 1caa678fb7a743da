#pragma once
// Verification off the simulated mark: the dose the beam really left is spread by the beam
// profile, thresholded by the material (driver/sim/part_image.hpp), seen by a camera with about
// seven pixels per module, and decoded by a real reader. The figures are grade-like, in the
// spirit of ISO/IEC TR 29158 (DPM verification): the module size the reader measured along each
// axis, axial non-uniformity (ISO/IEC 15415's |X − Y| / mean), and, against the intended module
// grid, how much of each module that should be marked is marked (fill) and how much of each that
// should stay bare is not (spill), and how many modules come out on the wrong side of half.
#include <optional>
#include <string>

#include "driver/sim/dose_raster.hpp"
#include "driver/sim/mark_response.hpp"
#include "driver/sim/part_image.hpp"
#include "marker/codes/code_marks.hpp"
#include "marker/codes/code_spec.hpp"

namespace mark {

struct CodeVerification {
  std::string reader;          // libdmtx or zbar
  bool decoded = false;
  std::string expected_data;   // what a reader should return (GS1: the element string)
  std::string decoded_data;
  bool data_match = false;     // decoded and equal, byte for byte
  double module_um = 0;        // intended module size
  // As the reader measured them (decoded symbols only; y and the non-uniformity are 2-D only).
  std::optional<double> module_x_um, module_y_um, axial_nonuniformity_pct;
  double fill_ratio = 0;       // mean marked share of the modules meant to be marked
  double fill_ratio_min = 0;   // the least marked of them
  double spill_ratio = 0;      // mean marked share of the modules meant to stay bare
  std::size_t modules_wrong = 0;  // modules on the wrong side of half marked
  double camera_px_um = 0;     // pixel of the camera image
  CameraImage image;           // the part as the camera sees it (for --dose-png)
};

struct VerifyOptions {
  MarkResponse response;
  double pixels_per_module = 7;  // camera resolution, as verifiers recommend (≥ 5 per module)
  double aperture_modules = 0.5; // synthetic aperture diameter, in modules (TR 29158: 0.5–0.8)
};

CodeVerification verify_code(const PlacedCode& code, const CodeSpec& spec, const DoseRaster& dose,
                             const VerifyOptions& options = {});

// ISO/IEC 15415 grade letter for axial non-uniformity: A ≤ 6 %, B ≤ 8 %, C ≤ 10 %, D ≤ 12 %, F.
char axial_nonuniformity_grade(double pct);

}  // namespace mark

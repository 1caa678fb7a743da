#pragma once
// The job runner's side of code verification: it photographs each code on the simulated part
// with the simulated reader's camera (driver/sim/camera_model.hpp) and hands the picture to the
// verifier (marker/codes/verify.hpp), which knows nothing of the simulator.
#include "driver/sim/camera_model.hpp"
#include "driver/sim/dose_raster.hpp"
#include "driver/sim/mark_response.hpp"
#include "marker/codes/verify.hpp"

namespace mark {

// How the codes of a job are read back.
struct CodeCheckOptions {
  MarkResponse response;   // the material: which fluence marks
  CameraSettings camera;   // the reader's camera and the light on the part
  VerifyOptions reading;   // synthetic aperture, which readers decide
  // The quality class's dose sufficiency against this material's energy per mm (`response`)
  // rather than each pen's own power / speed (--dose-reference material).
  bool dose_vs_material = false;
};

// What the camera is aimed at: the symbol, its quiet zone, two modules and the beam's reach around.
FieldWindow code_window(const PlacedCode& code, const MarkResponse& response);

// The simulated reader's picture of the code (a dark part when the code is inverted), with the
// part's marked share at the same pixels.
CodePicture code_picture(const PlacedCode& code, const DoseRaster& dose, const CodeCheckOptions& options);

// Photographed and verified.
CodeVerification check_code(const PlacedCode& code, const CodeSpec& spec, const DoseRaster& dose,
                            const CodeCheckOptions& options);

}  // namespace mark

#pragma once
// What a 2D or linear code accepts, wherever it is given: the --code-… options, a job file's code
// objects, the code library's checks; and the simulated reader's settings.
#include "marker/limits/value_range.hpp"

namespace mark {

inline const Range kCodePositionRange = length_range(-1000, 1000);
inline const Range kCodeAngleRange{-360, 360, "degrees"};
inline const Range kModuleRange = length_range(0.01, 20);
inline const Range kCodeSizeRange = length_range(0.05, 500);
inline const Range kBarHeightRange = length_range(0.1, 500);
inline const Range kDotShareRange{0.2, 1.5, "modules"};
inline const WholeRange kQrVersionRange{0, 40};  // 0: the smallest that holds the data
// The simulated part and reader.
inline const Range kBeamDiameterRange = length_range(0.001, 5);
inline const Range kLineWidthRange = length_range(0.001, 15);  // and at most 3 beam diameters
inline const Range kLineSpeedRange{1, 100000, "mm/s"};
inline const Range kApertureRange{0, 1.5, "modules"};
// The simulated reader's camera (--camera KEY=VALUE,…; driver/sim/camera_model.hpp).
inline const Range kCameraPixelRange{1, 1000, "µm", false, true};  // 0: automatic
inline const Range kCameraMinPixelRange{1, 1000, "µm"};
inline const Range kSensorSideRange{64, 20000, "pixels"};
inline const Range kSensorPixelRange{0.5, 50, "µm"};
inline const Range kFNumberRange{0.7, 64, ""};
inline const Range kWavelengthRange{300, 1100, "nm"};
inline const Range kDefocusRange{0, 5000, "µm"};
inline const Range kFalloffRange{0, 90, "%"};
inline const Range kExposureRange{10, 100, "%"};
inline const Range kFullWellRange{0.1, 1000, "thousand electrons"};
inline const Range kReadNoiseRange{0, 50, "grey levels"};
inline const Range kNoiseSeedRange{0, 4294967295.0, ""};
inline const Range kReflectanceRange{0.001, 1, ""};
inline const Range kToneRatioRange{1.01, 1000, ""};
inline const Range kGrainRange{0, 50, "%"};

}  // namespace mark

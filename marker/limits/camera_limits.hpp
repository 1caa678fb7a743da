#pragma once
// The simulated reader's camera: the KEY=VALUE items of `--camera` (marker/cli/code_options.cpp,
// driver/sim/camera_model.hpp). They are parts of one setting's value (kCamera in
// code_settings.hpp), not settings of their own, so they are ranges here rather than table rows.
#include "marker/limits/value_range.hpp"

namespace mark {

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

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
inline const Range kPixelsPerModuleRange{3, 20, ""};
inline const Range kApertureRange{0, 1.5, "modules"};

}  // namespace mark

#pragma once
// What the gravure engraver accepts, in one table, so the library's checks and the command line's
// option checks say the same thing ("--cell-rate: 50000 is outside the range 500 to 20000 Hz").
#include "marker/limits/value_range.hpp"

namespace mark {

// Screen and cylinder.
inline const Range kCellsPerMmRange{0.5, 100, "cells/mm"};  // 5 .. 1000 lines/cm
inline const Range kCellRateRange{500, 20000, "Hz"};        // ≥ 10 samples a cell
inline const Range kResolutionRange{0.5, 10000, "px/mm"};
inline const Range kStylusAngleRange{60, 160, "degrees"};
// Setup values (CT and LW).
inline const Range kCellDepthRange{1, 200, "µm"};
inline const Range kChannelDepthRange{0, 200, "µm"};
inline const Range kSetupGainRange{0.1, 5, ""};
inline const Range kSetupOffsetRange{-50, 50, "µm"};
inline const Range kLiftRange{0, 100, "µm"};
// Filters.
inline const Range kFilterFrequencyRange{1, 50000, "Hz"};
inline const Range kZeroDampingRange{0, 10, ""};
inline const Range kPoleDampingRange{0.001, 10, ""};
inline const Range kNotchDepthRange{0, 60, "dB"};
// The flat target response the filters are tuned to.
inline const Range kTargetCornerRange{11000, 45000, "Hz"};
// The simulated head.
inline const Range kModeFrequencyRange{100, 40000, "Hz"};
inline const Range kModeDampingRange{0.001, 0.99, ""};
inline const Range kModeGainRange{0.001, 10, ""};
inline const Range kSenseNoiseRange{0, 10, "µm"};

}  // namespace mark

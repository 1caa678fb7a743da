#pragma once
// The allowed range of every gravure parameter, in one table, so the library's checks and the
// command line's option checks say the same thing: "<name> <value>: outside <lo> .. <hi> <unit>".
#include <string>

namespace mark {

struct ParameterRange {
  double lo;
  double hi;
  const char* unit;  // "" for plain numbers
};

// Screen and cylinder.
inline constexpr ParameterRange kCellsPerMmRange{0.5, 100, "cells/mm"};  // 5 .. 1000 lines/cm
inline constexpr ParameterRange kCellRateRange{500, 20000, "Hz"};        // ≥ 10 samples a cell
inline constexpr ParameterRange kResolutionRange{0.5, 10000, "px/mm"};
inline constexpr ParameterRange kStylusAngleRange{60, 160, "deg"};
// Setup values (CT and LW).
inline constexpr ParameterRange kCellDepthRange{1, 200, "µm"};
inline constexpr ParameterRange kChannelDepthRange{0, 200, "µm"};
inline constexpr ParameterRange kSetupGainRange{0.1, 5, ""};
inline constexpr ParameterRange kSetupOffsetRange{-50, 50, "µm"};
inline constexpr ParameterRange kLiftRange{0, 100, "µm"};
// Filters.
inline constexpr ParameterRange kFilterFrequencyRange{1, 50000, "Hz"};
inline constexpr ParameterRange kZeroDampingRange{0, 10, ""};
inline constexpr ParameterRange kPoleDampingRange{0.001, 10, ""};
inline constexpr ParameterRange kNotchDepthRange{0, 60, "dB"};
// The simulated head.
inline constexpr ParameterRange kModeFrequencyRange{100, 40000, "Hz"};
inline constexpr ParameterRange kModeDampingRange{0.001, 0.99, ""};
inline constexpr ParameterRange kModeGainRange{0.001, 10, ""};
inline constexpr ParameterRange kSenseNoiseRange{0, 10, "µm"};
inline constexpr ParameterRange kDriveRange{1, 100000, "µm"};

// Throws InputError "<name> <value>: outside <lo> .. <hi> <unit>" unless lo ≤ value ≤ hi (and
// finite).
void check_range(const std::string& name, double value, const ParameterRange& range);

}  // namespace mark

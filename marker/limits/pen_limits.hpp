#pragma once
// What a laser pen and a head accept, wherever they are given (a job file's pens and head,
// `marker job new`). Speeds and ticks also depend on the head (its positioning limit, 20 % of its
// τ); those checks come with the head.
#include "marker/limits/value_range.hpp"

namespace mark {

inline const Range kSpotRange{1, 10000, "µm"};
inline const Range kPowerRange{0, 100, "%"};
inline const Range kFrequencyRange{0.1, 10000, "kHz"};
inline const Range kPulseWidthRange{0, 1e6, "ns"};   // 0: the source's default
inline const WholeRange kPassesRange{1, 100};
// Marking and jump speeds before the head's own limit is known.
inline const Range kSpeedRange{0.001, 100000, "mm/s"};
inline const Range kTickRange{1, 1000, "µs"};
// Blanking run-ins and run-outs: a few v·τ (under 1 mm at any head's speed); more only costs time.
inline const Range kExtensionRange = length_range(0, 10);

}  // namespace mark

#pragma once
// What `marker gcode` accepts for the settings of the second CNC round — V-carving and the
// machine's envelope — in one place, so they move together into the table of every setting.
// Engraving V-bits run from 10° (fine lettering) to 150° (wide, shallow signs).
#include "marker/limits/value_range.hpp"

namespace mark {

inline const Range kBitAngleRange{10, 170, "degrees"};
// 0: no cap but the bit's own diameter.
inline const Range kMaxDepthRange{0.001, 100, "mm", false, true};
// The clean-up end mill: 0.05 mm micro mills to a 50 mm fly cutter.
inline const Range kFlatBottomRange = length_range(0.05, 50);
// Below 0.5 µm the tolerance is finer than the program's 4 decimals (0.1 µm) can carry through
// the flattening and the axis; above 0.1 mm a carve visibly leaves its outline.
inline const Range kCarveToleranceRange = length_range(0.0005, 0.1);
// Stock and machine travel: a 0.1 mm sliver to the 10 m table of the largest field.
inline const Range kStockSizeRange = length_range(0.1, 10000);
inline const Range kTravelRange = length_range(1, 10000);

}  // namespace mark

#pragma once
// The values inside the machine envelope's options (--stock "W,H" / "X,Y,W,H", --travel "X,Y":
// cnc_settings.hpp's kStock, kTravel), read by marker/cli/machine_values.cpp: a 0.1 mm sliver
// to the 10 m table of the largest field.
#include "marker/limits/value_range.hpp"

namespace mark {

inline const Range kStockSizeRange = length_range(0.1, 10000);
inline const Range kTravelRange = length_range(1, 10000);

}  // namespace mark

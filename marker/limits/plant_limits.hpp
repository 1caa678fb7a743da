#pragma once
// The simulated head's plant: the KEY=VALUE items of `--plant` (marker/cli/plant_option.cpp,
// driver/sim/plant.hpp). They are parts of one setting's value (kPlant in head_settings.hpp), not
// settings of their own, so they are ranges here rather than table rows.
//
// The ranges are what a galvo of the presets' class can be and the simulator still integrates
// exactly: a lag off by up to ×2 either way, dead times up to 1 ms, resonances from 100 Hz to
// 100 kHz (below the 1 MHz sub-step's Nyquist frequency), accelerations from 1e3 to 1e10 mm/s², a
// current loop's lag from 5 µs (five sub-steps: its explicit step stays well damped).
#include "marker/limits/value_range.hpp"

namespace mark {

inline const Range kPlantTauScaleRange{0.5, 2, ""};
inline const Range kPlantWnScaleRange{0.5, 2, ""};
inline const Range kPlantDeadRange{0, 1000, "µs"};  // dead time and latency
inline const Range kPlantResonanceRange{100, 100000, "Hz", false, true};  // 0: none
inline const Range kPlantResonanceZetaRange{0.001, 1, ""};
inline const Range kPlantAccelRange{1e3, 1e10, "mm/s²", false, true};   // 0: the preset's
inline const Range kPlantBackEmfRange{100, 1e6, "mm/s", false, true};     // 0: none
inline const Range kPlantRmsAccelRange{1, 100, "%", false, true};        // 0: none
inline const Range kPlantThermalTauRange{1e-4, 100, "s"};
inline const Range kPlantCurrentTauRange{5, 1000, "µs", false, true};     // 0: none
inline const Range kPlantJerkRange{1e6, 1e16, "mm/s³", false, true};       // 0: none
inline const Range kPlantNoiseRange{0, 100, "µm"};
inline const Range kPlantSeedRange{0, 4294967295.0, ""};
inline const Range kPlantQuantRange{8, 24, "bits", false, true};          // 0: exact

}  // namespace mark

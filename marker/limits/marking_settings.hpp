#pragma once
// The settings of `marker mark` beyond the text, its layout, the head and the pen: a code marked
// with the text, the quality the simulator must predict before anything fires, device or virtual
// time; and `marker preview`'s (one declaration each, setting.hpp).
#include "marker/limits/setting.hpp"

namespace mark {

inline constexpr Text kCodeData{
    {"--code", "",
     "also mark a code: SYMBOLOGY:DATA (datamatrix, gs1-datamatrix, qr, code128, gs1-128); placed with the "
     "--code-… options, hatched with the --hatch-… options"},
    {}, "none"};
inline constexpr Toggle kVirtualTime{
    {"--virtual-time", "", "drain as fast as the device accepts (device time is still reported)"}};
inline constexpr Toggle kNoTravel{{"--no-travel", "", "preview: leave out the dashed travel between strokes"}};

inline constexpr SettingRef kMarkingSettingList[] = {&kCodeData, &kVirtualTime, &kNoTravel};
inline constexpr SettingTable kMarkingSettings{"marking", "Marking and previews", "", kMarkingSettingList};

}  // namespace mark

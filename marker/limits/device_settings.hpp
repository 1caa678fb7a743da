#pragma once
// The settings of the device a job runs on: which device, and how an LMC board is wired and
// driven (the lens field is the layout's --field); the red-pointer frame's (one declaration
// each, setting.hpp). A job file names only the device ("device").
#include "marker/limits/setting.hpp"

namespace mark {

inline constexpr Text kDevice{
    {"--device", "device",
     "device: sim (the simulated scanner), lmc or lmc:SERIAL (a BJJCZ board, see `marker devices`), "
     "lmc-capture:FILE (the board's bytes to a file)"},
    "sim", "`sim`; `frame`: `lmc`"};
inline constexpr Text kCorrectionFile{
    {"--cor", "", "LMC: EzCad field-correction file (.cor, both formats) to upload"}, {}, "none"};
inline constexpr Toggle kSwapXy{{"--swap-xy", "", "LMC: the head's x and y galvos are swapped"}};
inline constexpr Toggle kFlipX{{"--flip-x", "", "LMC: mirror x (the head's x galvo is wired reversed)"}};
inline constexpr Toggle kFlipY{{"--flip-y", "", "LMC: mirror y"}};
inline constexpr Choice kLaserSource{{"--source", "", "LMC: laser source"}, "fiber, mopa", "fiber"};
inline constexpr WholeRange kPortBitRange{0, 15};
inline constexpr Count kLaserBit{{"--laser-bit", "", "LMC: output-port bit that enables the laser"}, kPortBitRange, 0};
inline constexpr Count kRedBit{{"--red-bit", "", "LMC: output-port bit of the red pointer"}, kPortBitRange, 8};
inline constexpr Choice kPolygonDelayUnits{
    {"--polygon-delay-units", "", "LMC: PolygonDelay encoding: 10us (meerk40t since 2025) or us (galvoplotter)"},
    "10us, us", "10us"};
// Below 0.5 µm a chord is shorter than the board's 16-bit field step on any lens.
inline constexpr Quantity kChordTolerance{
    {"--chord-tolerance", "", "LMC: arcs become chords within this distance"}, {0.5, 1000, "µm"}, 5};

// `marker frame`: the red pointer tracing the job's outline.
inline constexpr Choice kFrameShape{{"--shape", "", "frame: what to trace"}, "box, hull, strokes", "box"};
inline constexpr Quantity kFrameSpeed{{"--speed", "", "frame: red-pointer speed"}, {0.001, 100000, "mm/s"}, 3000};
inline constexpr Count kFrameLaps{
    {"--laps", "", "frame: stop after this many laps (0: until Ctrl-C)"}, {0, 1'000'000'000}, 0};

inline constexpr SettingRef kDeviceSettingList[] = {
    &kDevice,  &kCorrectionFile,    &kSwapXy,         &kFlipX,      &kFlipY,      &kLaserSource,
    &kLaserBit, &kRedBit, &kPolygonDelayUnits, &kChordTolerance, &kFrameShape, &kFrameSpeed, &kFrameLaps};
inline constexpr SettingTable kDeviceSettings{"device", "Device", "", kDeviceSettingList};

}  // namespace mark

#pragma once
// The settings of the device a job runs on: which device, and how an LMC board is wired and
// driven (the lens field is the layout's --field); the red-pointer frame's (one declaration
// each, setting.hpp). A job file names only the device ("device").
#include "marker/limits/setting.hpp"

namespace mark {

inline constexpr Text kDevice{
    {"--device", "device",
     "device: sim (the simulated scanner), lmc or lmc:SERIAL (a BJJCZ board, see `marker devices`), "
     "lmc-capture:FILE (the board's bytes to a file), lmc-emulated[:VARIANT] (the emulated board and the simulated scanner); with --job the job's unless given"},
    "sim", "`sim`; `frame`: `lmc`"};
inline constexpr Text kProbeDevice{
    {"--device", "", "lmc probe: the board: lmc, lmc:SERIAL (see `marker devices`) or lmc-emulated[:VARIANT]"}, "lmc"};
inline constexpr Text kCorrectionFile{
    {"--cor", "", "LMC: EzCad field-correction file (.cor, both formats) to upload"}, {}, "none"};
// On by default: EzCad's axes (lmc::kEzCadAxes; lmc_options.cpp asserts they agree).
inline constexpr Toggle kSwapXy{
    {"--swap-xy", "", "LMC: the first coordinate word is y (EzCad's default); --no-swap-xy: it is x"}, true};
inline constexpr Toggle kFlipX{{"--flip-x", "", "LMC: mirror x (the head's x galvo is wired reversed)"}};
inline constexpr Toggle kFlipY{{"--flip-y", "", "LMC: mirror y"}};
inline constexpr WholeRange kPortBitRange{0, 15};
inline constexpr Count kLaserBit{{"--laser-bit", "", "LMC: output-port bit that enables the laser"}, kPortBitRange, 0};
inline constexpr Count kRedBit{{"--red-bit", "", "LMC: output-port bit of the red pointer"}, kPortBitRange, 8};
inline constexpr Choice kPolygonDelayUnits{
    {"--polygon-delay-units", "",
     "LMC: PolygonDelay encoding: us (galvoplotter, balor) or 10us (meerk40t since 2025); "
     "`marker lmc probe` measures which a board takes"},
    "us, 10us", "us"};
inline constexpr Toggle kWordTicks{
    {"--word-ticks", "",
     "LMC: the board spends a tick on every word that is not a move (`marker lmc probe`: \"a parameter word "
     "takes a tick\"); timed moves then give those ticks back"}};
// Below 0.5 µm a chord is shorter than the board's 16-bit field step on any lens.
inline constexpr Quantity kChordTolerance{
    {"--chord-tolerance", "", "LMC: arcs become chords within this distance"}, {0.5, 1000, "µm"}, 5};

// `marker frame`: the red pointer tracing the job's outline.
inline constexpr Choice kFrameShape{{"--shape", "", "frame: what to trace"}, "box, hull, strokes", "box"};
inline constexpr Quantity kFrameSpeed{{"--speed", "", "frame: red-pointer speed"}, {0.001, 100000, "mm/s"}, 3000};
inline constexpr Count kFrameLaps{
    {"--laps", "", "frame: stop after this many laps (0: until Ctrl-C)"}, {0, 1'000'000'000}, 0};

inline constexpr Toggle kNoOrientationMark{
    {"--no-orientation-mark", "", "frame: trace only the job's outline, not the F at its +x side"}};

// What only an LMC board reads (a real one, its capture or the emulated one), not the simulated
// scanner.
inline constexpr SettingRef kLmcSettingList[] = {&kCorrectionFile, &kSwapXy, &kFlipX,             &kFlipY,
                                                 &kLaserBit,       &kRedBit, &kPolygonDelayUnits, &kWordTicks,
                                                 &kChordTolerance};

inline constexpr SettingRef kDeviceSettingList[] = {
    &kDevice,  &kProbeDevice, &kCorrectionFile,    &kSwapXy,         &kFlipX,      &kFlipY,
    &kLaserBit, &kRedBit, &kPolygonDelayUnits, &kWordTicks, &kChordTolerance, &kFrameShape, &kFrameSpeed, &kFrameLaps,
    &kNoOrientationMark};
inline constexpr SettingTable kDeviceSettings{"device", "Device", "", kDeviceSettingList};

}  // namespace mark

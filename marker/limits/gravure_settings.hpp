#pragma once
// The settings of the gravure engraver (`marker gravure`'s options, one declaration each,
// setting.hpp) and the ranges of the structured values it takes (a screen, head resonances,
// filter sections), so the library's checks and the command line's say the same thing
// ("--cell-rate: 50000 is outside the range 500 to 20000"). The defaults are the library's
// (marker/gravure/, driver/sim/sim_stylus_head.hpp; a test keeps them equal).
#include <cstdint>

#include "marker/limits/setting.hpp"

namespace mark {

// Screen and cylinder.
inline constexpr Bounds kCellsPerMmBounds{0.5, 100, "cells/mm"};  // 5 .. 1000 lines/cm
inline constexpr Text kScreen{{"--screen", "", "screen in lines/cm: ALONG or ALONGxACROSS (5 to 1000 lines/cm)"},
                              "70"};
// ≥ 10 samples a cell at the 200 kHz stylus clock.
inline constexpr Bounds kCellRateBounds{500, 20000, "Hz"};
inline constexpr Count kCellRate{{"--cell-rate", "", "cells engraved per second (Hz)"},
                                 {static_cast<std::int64_t>(kCellRateBounds.min),
                                  static_cast<std::int64_t>(kCellRateBounds.max)},
                                 6250};
inline constexpr Bounds kResolutionBounds{0.5, 10000, "px/mm"};
inline constexpr Quantity kResolution{
    {"--resolution", "", "image pixels per mm (0: 4 a cell along the track)"},
    {kResolutionBounds.min, kResolutionBounds.max, kResolutionBounds.unit, false, true}, 0};
inline constexpr Toggle kStagger{{"--stagger", "", "offset odd tracks by half a cell"}};
// Setup values (CT: continuous tone, LW: line-work).
inline constexpr Bounds kCellDepthBounds{1, 200, "µm"};
inline constexpr Bounds kChannelDepthBounds{0, 200, "µm"};
inline constexpr Bounds kSetupGainBounds{0.1, 5, ""};
inline constexpr Bounds kSetupOffsetBounds{-50, 50, "µm"};
inline constexpr Quantity kCtDepth{{"--ct-depth", "", "CT full-cell depth (100 % cell)"}, kCellDepthBounds, 40};
inline constexpr Quantity kCtChannel{
    {"--ct-channel", "", "CT channel depth between 100 % cells"}, kChannelDepthBounds, 8};
inline constexpr Quantity kCtGain{{"--ct-gain", "", "CT gain on the density"}, kSetupGainBounds, 1};
inline constexpr Quantity kCtOffset{{"--ct-offset", "", "CT offset added to every depth"}, kSetupOffsetBounds, 0};
inline constexpr Quantity kLwDepth{{"--lw-depth", "", "LW full-cell depth (100 % cell)"}, kCellDepthBounds, 30};
inline constexpr Quantity kLwChannel{
    {"--lw-channel", "", "LW channel depth between 100 % cells"}, kChannelDepthBounds, 16};
inline constexpr Quantity kLwGain{{"--lw-gain", "", "LW gain on the density"}, kSetupGainBounds, 1};
inline constexpr Quantity kLwOffset{{"--lw-offset", "", "LW offset added to every depth"}, kSetupOffsetBounds, 0};
inline constexpr Quantity kLift{{"--lift", "", "stylus height above the surface over white"}, {0, 100, "µm"}, 5};
inline constexpr Quantity kStylusAngle{
    {"--stylus-angle", "", "diamond's included angle"}, {60, 160, "degrees"}, 120};

// The simulated head and its filters.
inline constexpr Bounds kModeFrequencyBounds{100, 40000, "Hz"};
inline constexpr Bounds kModeDampingBounds{0.001, 0.99, ""};
inline constexpr Bounds kModeGainBounds{0.001, 10, ""};
inline constexpr Bounds kFilterFrequencyBounds{1, 50000, "Hz"};
inline constexpr Bounds kZeroDampingBounds{0, 10, ""};
inline constexpr Bounds kPoleDampingBounds{0.001, 10, ""};
inline constexpr Bounds kNotchDepthBounds{0, 60, "dB"};
inline constexpr Text kStylusHead{
    {"--head", "", "the simulated head's resonances FREQ_HZ:DAMPING:GAIN,… (at most 4)"}, {},
    "1800:0.06:0.8,5500:0.04:0.2"};
inline constexpr Text kNominalHead{
    {"--nominal-head", "", "the head model the default filters are designed for"}, {}, "the typical head"};
inline constexpr Quantity kSenseNoise{{"--sense-noise", "", "sensing coil noise, rms"}, {0, 10, "µm"}, 0.02};
inline constexpr Quantity kSenseVelocityNoise{
    {"--sense-velocity-noise", "", "sensing coil velocity noise, rms"}, {0, 100000, "µm/s"}, 200};
inline constexpr Choice kTune{
    {"--tune", "", "filters: auto (measure and fit the head), nominal (designed for --nominal-head), off"},
    "auto, nominal, off", "nominal"};
inline constexpr Choice kTuneFrom{
    {"--tune-from", "", "what --tune auto measures the head from: both (position and velocity fused), position, velocity"},
    "both, position, velocity", "both"};
inline constexpr Text kNotch{
    {"--notch", "", "a notch filter by hand, FREQ_HZ:DAMPING:DEPTH_DB (repeatable)"}, {}, "none"};
inline constexpr Text kEmphasis{
    {"--emphasis", "", "the emphasis filter by hand, FREQ_HZ:DAMPING:CORNER_HZ:CORNER_DAMPING"}, {}, "none"};
// The flat target response the filters are tuned to.
inline constexpr Quantity kTargetCorner{
    {"--target", "", "corner of the flat target response"}, {11000, 45000, "Hz"}, 20000};
inline constexpr Toggle kRealTime{
    {"--real-time", "", "drain at the stylus clock (default: virtual time, as fast as possible)"}};
inline constexpr Toggle kNoCompare{{"--no-compare", "", "skip the engraving without filters"}};

inline constexpr SettingRef kGravureSettingList[] = {
    &kScreen,  &kCellRate,  &kResolution, &kStagger,      &kCtDepth,     &kCtChannel, &kCtGain, &kCtOffset,
    &kLwDepth, &kLwChannel, &kLwGain,     &kLwOffset,     &kLift,        &kStylusAngle, &kStylusHead,
    &kNominalHead, &kSenseNoise, &kSenseVelocityNoise, &kTune, &kTuneFrom, &kNotch,        &kEmphasis,    &kTargetCorner, &kRealTime, &kNoCompare};
inline constexpr SettingTable kGravureSettings{"gravure", "Gravure", "", kGravureSettingList};

}  // namespace mark

#pragma once
// The settings of `marker peen`: the dot font, the planner and the marking window, and the
// simulated pin-marker gantry's time model (one declaration each, setting.hpp). The gantry's
// options set both axes at once or one axis (the per-axis option wins).
#include "marker/limits/setting.hpp"

namespace mark {

inline constexpr Text kDotFont{
    {"--font", "",
     "dot-matrix font 5x7, 7x9 or 10x16; or a stroke font (`builtin`, an installed name, a .jhf/.lff/.cxf file) "
     "marked as dots along its strokes"},
    "5x7"};
inline constexpr Choice kPlanner{{"--planner", "", "needle path planner"}, "snake, block, optimized", "optimized"};
inline constexpr Text kWindow{
    {"--window", "",
     "marking window WIDTHxHEIGHT in mm, centred on the field; the whole-window snake sweeps all of it"},
    {}, "the dots' bounding box"};
// Neighbouring dots at least 4 motor steps apart and at most a letter's height (checked once the
// gantry and the height are known: marker/cli/peen_command.cpp).
inline constexpr Quantity kPitch{
    {"--pitch", "", "dot pitch along strokes for stroke fonts (at least 4 motor steps, at most the height)"},
    {0, 10000, "mm", true}, {}, "the height / 10"};
inline constexpr Toggle kBlockStraight{
    {"--block-straight", "", "let the block snake move both axes together (not the patent's track)"}};

// Pin markers run 20–200 steps per mm, 50–300 mm/s and 1–10 m/s²; the ranges leave room on both
// sides without letting a number reach where the time model stops meaning anything. The
// defaults are the gantry's (marker/peen/gantry.hpp).
inline constexpr Bounds kStepsBounds{1, 10000, "steps/mm"};
inline constexpr Bounds kGantrySpeedBounds{1, 5000, "mm/s"};
inline constexpr Bounds kGantryAccelBounds{10, 100000, "mm/s²"};
inline constexpr Quantity kStepsPerMm{{"--steps-per-mm", "", "motor steps per mm, both axes"}, kStepsBounds, 40};
inline constexpr Quantity kXStepsPerMm{{"--x-steps-per-mm", "", "motor steps per mm, X axis"}, kStepsBounds, {},
                                       "--steps-per-mm"};
inline constexpr Quantity kYStepsPerMm{{"--y-steps-per-mm", "", "motor steps per mm, Y axis"}, kStepsBounds, {},
                                       "--steps-per-mm"};
inline constexpr Quantity kGantrySpeed{{"--speed", "", "gantry top speed, both axes"}, kGantrySpeedBounds, 150};
inline constexpr Quantity kXSpeed{{"--x-speed", "", "gantry top speed, X axis"}, kGantrySpeedBounds, {}, "--speed"};
inline constexpr Quantity kYSpeed{{"--y-speed", "", "gantry top speed, Y axis"}, kGantrySpeedBounds, {}, "--speed"};
inline constexpr Quantity kGantryAccel{{"--accel", "", "gantry acceleration, both axes"}, kGantryAccelBounds, 3000};
inline constexpr Quantity kXAccel{{"--x-accel", "", "gantry acceleration, X axis"}, kGantryAccelBounds, {}, "--accel"};
inline constexpr Quantity kYAccel{{"--y-accel", "", "gantry acceleration, Y axis"}, kGantryAccelBounds, {}, "--accel"};
inline constexpr Quantity kStrike{{"--strike-ms", "", "time per needle strike"}, {0, 1000, "ms"}, 5};

inline constexpr SettingRef kPeenSettingList[] = {
    &kDotFont,     &kPlanner,     &kWindow,  &kPitch,  &kBlockStraight, &kStepsPerMm, &kXStepsPerMm, &kYStepsPerMm,
    &kGantrySpeed, &kXSpeed,      &kYSpeed,  &kGantryAccel, &kXAccel,   &kYAccel,     &kStrike};
inline constexpr SettingTable kPeenSettings{"peen", "Dot peen", "", kPeenSettingList};

}  // namespace mark

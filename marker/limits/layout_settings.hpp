#pragma once
// The settings of a text's layout: the layout options of every command that takes text, and a
// job file's text objects (one declaration each, setting.hpp). Positions and radii stay within
// the largest field (10 m, head_settings.hpp's kField); the layout then checks the text against
// the field it is marked in.
#include "marker/limits/setting.hpp"

namespace mark {

inline constexpr Text kFont{
    {"--font", "font", "font: `builtin`, an installed font name (see `marker fonts`) or a .jhf/.lff/.cxf file"},
    "builtin"};
// 10 µm letters are below any laser spot; 10 m letters fill the largest field.
inline constexpr Quantity kHeight{{"--height", "height_mm", "character (cap) height"}, {0.01, 10000, "mm"}, 5};
inline constexpr Quantity kWidthFactor{
    {"--width-factor", "width_factor", "horizontal scale of the letters"}, {0.05, 20, ""}, 1};
// Letters that step backwards are refused by the layout (the gap must exceed −advance).
inline constexpr Quantity kGap{
    {"--gap", "gap_mm", "extra gap between letters (letters may not step backwards)"}, {-10000, 10000, "mm"}, 0};
// Below half the font's line height, lines print over each other.
inline constexpr Quantity kLineSpacing{
    {"--line-spacing", "line_spacing", "factor on the font's line height"}, {0.5, 20, ""}, 1};
inline constexpr Choice kAlign{{"--align", "align", "alignment of each line about the base point"},
                               "left, center, right", "left", "`left`; `peen`: `center`"};
inline constexpr Bounds kPositionBounds{-10000, 10000, "mm"};
inline constexpr Quantity kX{{"--x", "x_mm", "base point x (field frame; inside the field)"}, kPositionBounds, 0};
inline constexpr Quantity kY{{"--y", "y_mm", "base point y (first baseline; inside the field)"}, kPositionBounds, 0};
// A milling machine's text (`marker gcode`): no galvo field, the work coordinates inside the travel.
inline constexpr Quantity kWorkX{{"--x", "", "base point x (work coordinates; inside the --travel)"}, kPositionBounds, 0};
inline constexpr Quantity kWorkY{
    {"--y", "", "base point y (first baseline; work coordinates; inside the --travel)"}, kPositionBounds, 0};
inline constexpr Bounds kAngleBounds{-360, 360, "degrees"};
inline constexpr Quantity kAngle{
    {"--angle", "angle_deg", "inclined fitting: rotate the text about the base point"}, kAngleBounds, 0};
inline constexpr Text kCircle{
    {"--circle", "circle",
     "circular fitting around a centre with a radius: CX,CY,R in mm; a job file: the object below"},
    {}, "none"};
inline constexpr Quantity kCircleX{{"", "circle.cx_mm", "circular fitting: centre x"}, kPositionBounds, 0};
inline constexpr Quantity kCircleY{{"", "circle.cy_mm", "circular fitting: centre y"}, kPositionBounds, 0};
inline constexpr Quantity kCircleRadius{
    {"", "circle.radius_mm", "circular fitting: radius (required)"}, {0, 10000, "mm", true}, {}};
inline constexpr Quantity kStartAngle{
    {"--start-angle", "circle.start_angle_deg", "circular fitting: angle where the text starts"},
    kAngleBounds, {}, "self-centred"};
inline constexpr Toggle kSelfCentred{
    {"--self-centred,--self-centered", "",
     "circular fitting: centre the text on the top (bottom with --inside) of the circle (the default)"}};
inline constexpr Toggle kInside{
    {"--inside", "circle.inside", "circular fitting: letters inside the circle, reading along its bottom"}};
// Beyond ±75° the shear slants a letter more than 3.7 times its height sideways.
inline constexpr Quantity kItalic{{"--italic", "italic_deg", "font inclination (shear)"}, {-75, 75, "degrees"}, 0};
// F-Engrave's spacing, in % of the character height: letters may overlap by up to half the
// height, or stand ten heights apart; a space from nothing to ten heights.
inline constexpr Quantity kCharSpacing{
    {"--char-spacing", "", "gap after each letter's drawing, % of the character height (F-Engrave's character spacing)"},
    {-50, 1000, "% of the character height"}, {}, "the font's own"};
inline constexpr Quantity kWordSpacing{
    {"--word-spacing", "", "advance of a space, % of the character height"}, {0, 1000, "% of the character height"}, {},
    "the font's own"};
inline constexpr Toggle kMirror{
    {"--mirror", "mirror", "mirror the text (reverse the letter order, mirror each letter)"}};
inline constexpr Toggle kReplaceMissing{
    {"--replace-missing", "replace_missing", "draw the font's replacement glyph for characters it lacks"}};
inline constexpr Choice kOrder{
    {"--order", "order", "stroke order: glyph (as the font draws), shortest (least jumping)"}, "glyph, shortest",
    "glyph"};

inline constexpr SettingRef kLayoutSettingList[] = {
    &kFont,   &kHeight,  &kWidthFactor, &kGap,    &kLineSpacing, &kAlign,  &kX,        &kY,
    &kAngle,  &kCircle,  &kCircleX,     &kCircleY, &kCircleRadius, &kStartAngle, &kSelfCentred, &kInside,
    &kWorkX,  &kWorkY,    &kCharSpacing, &kWordSpacing,
    &kItalic, &kMirror,  &kReplaceMissing, &kOrder};
inline constexpr SettingTable kLayoutSettings{"layout", "Layout of a text object", "objects[]", kLayoutSettingList};

}  // namespace mark

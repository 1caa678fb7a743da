#pragma once
// The settings of a hatch fill (a filled text, a code's modules): the --fill, --hatch-… and
// --contour-… options and a job file's "fill" and "hatch" objects (one declaration each,
// setting.hpp); and the ranges the fill library checks beyond them.
#include "marker/limits/setting.hpp"

namespace mark {

inline constexpr Choice kFill{{"--fill", "", "fill outline-font letters (a job file: a \"fill\" object)"}, "none, hatch",
                              "none"};
inline constexpr Choice kFillRule{
    {"--fill-rule", "rule", "inside of overlapping outlines: nonzero (TrueType, CFF), evenodd (text only)"},
    "nonzero, evenodd", "nonzero"};
// A little under the default 40 µm line, so the lines of a hatch overlap into a solid fill.
inline constexpr Quantity kHatchSpacing{
    {"--hatch-spacing", "spacing_mm",
     "distance between hatch lines (a list on the command line, or \"sets\": one per hatch set)"},
    {0.001, 10, "mm"}, 0.035};
inline constexpr Quantity kHatchAngle{
    {"--hatch-angle", "angle_deg",
     "hatch direction (a list on the command line, or \"sets\": several hatch sets, e.g. 0,90; a code's from its "
     "rows or bars)"},
    {-360, 360, "degrees"}, 0};
inline constexpr WholeRange kHatchSetsRange{1, 8};
inline constexpr Choice kHatchDirection{
    {"--hatch-direction", "direction", "bidirectional (serpentine) or unidirectional lines"},
    "bidirectional, unidirectional", "bidirectional"};
inline constexpr Choice kHatchOrder{
    {"--hatch-order", "order", "short (blocks ordered to keep jumps short) or raster (scanline order)"},
    "short, raster", "short"};
// Insets: a few beam radii; more than 5 mm leaves nothing of any letter.
inline constexpr Bounds kInsetBounds{0, 5, "mm"};
inline constexpr Quantity kHatchInset{
    {"--hatch-inset", "inset_mm", "hatch lines end this far inside the outline"}, kInsetBounds, {},
    "the beam radius (a job file: the spot's)"};
inline constexpr Count kContourPasses{
    {"--contour-passes", "contour_passes", "loops along the outline (0: hatch only)"}, {0, 100}, 0};
inline constexpr Choice kContourPlacement{
    {"--contour-placement", "contour_placement", "contour passes before or after the hatch"}, "before, after",
    "before"};
inline constexpr Quantity kContourInset{
    {"--contour-inset", "contour_inset_mm", "first contour loop inside the outline"}, kInsetBounds, {},
    "the beam radius (a job file: the spot's)"};
inline constexpr Quantity kContourSpacing{
    {"--contour-spacing", "contour_spacing_mm", "between contour loops"}, {0.001, 10, "mm"}, {},
    "the hatch spacing"};

// What the fill library checks beyond the settings (fill_options.hpp).
inline constexpr Bounds kMinHatchLineBounds{0, 1, "mm"};
inline constexpr Bounds kFillChordBounds{1e-5, 0.01, "mm"};

inline constexpr SettingRef kFillSettingList[] = {
    &kFill,       &kFillRule,      &kHatchSpacing,     &kHatchAngle,   &kHatchDirection, &kHatchOrder,
    &kHatchInset, &kContourPasses, &kContourPlacement, &kContourInset, &kContourSpacing};
// What a hatch fill reads, of a filled text or of a code's modules: all but --fill and its rule.
inline constexpr std::span<const SettingRef> kHatchSettingList = std::span(kFillSettingList).subspan(2);
static_assert(kFillSettingList[0] == SettingRef{&kFill} && kFillSettingList[1] == SettingRef{&kFillRule});

inline constexpr SettingTable kFillSettings{"fill", "Hatch fill", "objects[].fill, objects[].hatch",
                                            kFillSettingList};

}  // namespace mark

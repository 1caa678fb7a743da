#pragma once
// The settings of CNC engraving (`marker gcode`) and of measuring a cutter from its shadow
// (`marker tool-measure`), one declaration each (setting.hpp). Engraving cutters run from 0.1 to
// 12 mm, feeds from a few to a few thousand mm/min; the ranges leave room on both sides and keep
// every number a controller can be given. The defaults are the library's (marker/cnc/; a test
// keeps them equal).
#include "marker/limits/setting.hpp"

namespace mark {

inline constexpr Choice kCncMode{
    {"--mode", "",
     "depression: tool centre on the strokes; protrusion: pocket around the letters; v-carve: V-bit on the medial "
     "axis of outline letters"},
    "depression, protrusion, v-carve", "depression"};
inline constexpr Quantity kToolDiameter{{"--tool-diameter", "", "cutter diameter"}, {0.01, 50, "mm"}, 1};
inline constexpr Quantity kDepth{{"--depth", "", "engraving depth below the surface"}, {0.001, 50, "mm"}, 0.2};
inline constexpr Quantity kDepthPerPass{
    {"--depth-per-pass", "", "at most this deep per pass (0: one pass)"}, {0.001, 50, "mm", false, true}, 0};
inline constexpr Quantity kSafeZ{{"--safe-z", "", "height for rapid moves"}, {0.1, 1000, "mm"}, 5};
inline constexpr Bounds kFeedBounds{1, 100000, "mm/min"};
inline constexpr Quantity kFeed{{"--feed", "", "cutting feed"}, kFeedBounds, 300};
inline constexpr Quantity kPlungeFeed{{"--plunge-feed", "", "plunge feed"}, kFeedBounds, 100};
inline constexpr Quantity kSpindle{
    {"--spindle", "", "spindle speed (0: no M3/M5)"}, {1, 200000, "rpm", false, true}, 10000};
inline constexpr Choice kDialect{
    {"--dialect", "", "linuxcnc (o-word subprograms), fanuc (O/M98/M99), plain (grbl, inlined; also: grbl)"},
    "linuxcnc, fanuc, plain, grbl", "linuxcnc"};
inline constexpr Choice kUnits{{"--units", "", "output units: mm (G21) or inch (G20; also: in)"}, "mm, inch, in",
                               "mm"};
inline constexpr Text kHeader{
    {"--header", "", "line after the program's modal preamble (repeatable)"}, {}, "none"};
inline constexpr Text kFooter{{"--footer", "", "line before the program end (repeatable)"}, {}, "none"};
inline constexpr Text kTitle{{"--title", "", "comment at the top of the program"}, {}, "the mode and the text"};
inline constexpr Toggle kM2{{"--m2", "", "end with M2 instead of M30"}};
// Below 1 µm the tolerance is finer than the program's 4 decimals can write.
inline constexpr Quantity kArcTolerance{
    {"--arc-tolerance", "", "how far arc splines of elliptical arcs may leave the curve"}, {0.001, 1, "mm"}, 0.005};
inline constexpr Toggle kEllipseChords{
    {"--ellipse-chords", "", "cut elliptical arcs as G01 chords instead of biarcs"}};
inline constexpr Quantity kStrokeWidth{
    {"--stroke-width", "", "protrusion: width of the raised strokes (0: the tool diameter)"},
    {0.01, 100, "mm", false, true}, 0};
inline constexpr Quantity kMargin{
    {"--margin", "", "protrusion: letters to boundary rectangle (0: 2 × the tool diameter)"},
    {0.01, 1000, "mm", false, true}, 0};
// Pocket loops closer than 5 % of the tool diameter only multiply the cutting time (checked
// once the tool is known: marker/cli/gcode_command.cpp).
inline constexpr Quantity kStepover{
    {"--stepover", "",
     "protrusion and v-carve clean-up: between pocket loops (0: 40 % of the tool diameter; else 5 % of the diameter "
     "to its radius)"},
    {0.001, 25, "mm", false, true}, 0};
inline constexpr Toggle kCutterComp{
    {"--cutter-comp", "", "protrusion: program the walls as part contours with G41 and the tool diameter in D"}};

// V-carving (--mode v-carve only; refused with another mode). Engraving V-bits run from 10°
// (fine lettering) to 150° (wide, shallow signs).
inline constexpr Quantity kBitAngle{
    {"--bit-angle", "", "v-carve: included angle of the V-bit"}, {10, 170, "degrees"}, 60};
inline constexpr Quantity kMaxDepth{
    {"--max-depth", "", "v-carve: deepest cut; deeper places get a flat bottom (0: no cap)"},
    {0.001, 100, "mm", false, true}, {}, "what the bit's diameter can cut"};
// The clean-up end mill: 0.05 mm micro mills to a 50 mm fly cutter.
inline constexpr Quantity kFlatBottom{
    {"--flat-bottom", "", "v-carve: diameter of the end mill that clears the flat bottoms (needs --cleanup-output)"},
    {0.05, 50, "mm"}, {}, "none"};
// Below 0.5 µm the tolerance is finer than the program's 4 decimals (0.1 µm) can carry through
// the flattening and the axis; above 0.1 mm a carve visibly leaves its outline.
inline constexpr Quantity kCarveTolerance{
    {"--carve-tolerance", "", "v-carve: how far the carve may stray from the exact medial axis"},
    {0.0005, 0.1, "mm"}, 0.002};
inline constexpr Choice kCarveFillRule{
    {"--fill-rule", "", "v-carve: inside of overlapping outlines (nonzero: TrueType, CFF)"}, "nonzero, evenodd", {},
    "nonzero"};
// The machine's envelope: the values are checked by marker/cli/machine_values.cpp against
// cnc_limits.hpp's ranges (a 0.1 mm sliver to the 10 m table of the largest field).
inline constexpr Text kStock{
    {"--stock", "", "the stock: W,H with its lower-left corner at X0 Y0, or X,Y,W,H; every cut must lie on it (mm)"},
    {}, "none"};
inline constexpr Text kTravel{
    {"--travel", "", "the machine's travel X,Y: the largest the program may span (mm)"}, {}, "10000,10000 (the largest table)"};

// A cutter's shadow image (`tool-measure`, and `gcode --tool-image`): micrometres per pixel at
// the tool, from a microscope (0.01 µm) to a flatbed scan (10 mm).
inline constexpr Quantity kPixelSize{
    {"--pixel-size", "", "tool image: micrometres per pixel at the tool (required with an image)"},
    {0.01, 10000, "µm"}, {}, "required"};
inline constexpr Quantity kNominalDiameter{
    {"--nominal-diameter", "", "tool-measure: the diameter the toolpaths assume"}, {0.001, 1000, "mm"}, {}, "none"};
inline constexpr Quantity kTangentialAngle{
    {"--tangential-angle", "",
     "tool-measure: scans more than this far from the edge normal are dropped (90 keeps all)"},
    {0, 90, "degrees", true}, 60};

inline constexpr SettingRef kCncSettingList[] = {
    &kCncMode, &kToolDiameter, &kDepth,        &kDepthPerPass, &kSafeZ,    &kFeed,      &kPlungeFeed,
    &kSpindle, &kDialect,      &kUnits,        &kHeader,       &kFooter,   &kTitle,     &kM2,
    &kArcTolerance, &kEllipseChords, &kStrokeWidth, &kMargin, &kStepover, &kCutterComp, &kPixelSize,
    &kNominalDiameter, &kTangentialAngle, &kBitAngle, &kMaxDepth, &kFlatBottom, &kCarveTolerance, &kCarveFillRule,
    &kStock, &kTravel};
inline constexpr SettingTable kCncSettings{"cnc", "CNC engraving and tool measurement", "", kCncSettingList};

}  // namespace mark

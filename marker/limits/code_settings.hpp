#pragma once
// The settings of a 2D or linear code: `marker code`'s options (`marker mark` prefixes them:
// --code-module), a job file's code objects and the code library's checks; and the simulated
// part and reader a mark is verified on (one declaration each, setting.hpp).
#include "marker/limits/setting.hpp"

namespace mark {

inline constexpr Toggle kCodeEscapes{
    {"--escapes", "escapes", "interpret \\G \\R \\E \\xHH \\n \\\\ in the code's data"}};
inline constexpr Quantity kCodeSize{
    {"--size", "size_mm", "symbol width without quiet zone (or give the module size)"}, {0.05, 500, "mm"}, {},
    "from the module size"};
inline constexpr Quantity kModule{{"--module", "module_mm", "module size (or give the symbol's width)"},
                                  {0.01, 20, "mm"}, {}, "0.25"};
inline constexpr Quantity kBarHeight{{"--bar-height", "bar_height_mm", "linear codes: bar height"},
                                     {0.1, 500, "mm"}, {}, "15 % of the width, at least 5 modules"};
inline constexpr Text kMatrixSize{
    {"--matrix-size", "matrix_size", "Data Matrix: a fixed size ROWSxCOLS, e.g. 16x16, 16x48"}, {}, "automatic"};
inline constexpr Choice kMatrixShape{
    {"--shape", "shape", "Data Matrix automatic size"}, "square, rectangular, any", "square"};
inline constexpr Choice kQrEcc{{"--qr-ecc", "qr_ecc", "QR error correction"}, "L, M, Q, H", "M"};
inline constexpr Count kQrVersion{
    {"--qr-version", "qr_version", "QR version (0: the smallest that holds the data)"}, {0, 40}, 0};
inline constexpr Choice kModuleStyle{
    {"--style", "style", "code modules as square (hatched), dot, line (rows of lines)"}, "square, dot, line", "square"};
inline constexpr Choice kDotShape{{"--dot", "dot", "dot style"}, "spiral, circle", "spiral"};
inline constexpr Quantity kDotSize{
    {"--dot-size", "dot_size", "dot diameter (outer edge of the burn) as a share of the module"},
    {0.2, 1.5, "modules"}, 1};
inline constexpr Toggle kCodeInvert{
    {"--invert", "invert", "mark the light modules and the quiet zone (a dark part whose marks turn light)"}};
inline constexpr Bounds kCodePositionBounds{-1000, 1000, "mm"};
inline constexpr Quantity kCodeX{{"--x", "x_mm", "code centre x (field frame)"}, kCodePositionBounds, 0};
inline constexpr Quantity kCodeY{{"--y", "y_mm", "code centre y (field frame)"}, kCodePositionBounds, 0};
inline constexpr Quantity kCodeAngle{{"--angle", "angle_deg", "rotation of the code"}, {-360, 360, "degrees"}, 0};

// The simulated part and reader (`marker code`, `marker mark` with a code).
inline constexpr Quantity kBeamDiameter{
    {"--beam-diameter", "", "1/e² beam diameter on the part (its radius insets every fill)"}, {0.001, 5, "mm"},
    0.04};
inline constexpr Quantity kLineWidth{
    {"--line-width", "", "material: a single line at --line-speed marks this wide (at most 3 beam diameters)"},
    {0.001, 15, "mm"}, 0.04};
inline constexpr Quantity kLineSpeed{
    {"--line-speed", "", "material: speed of that reference line"}, {1, 100000, "mm/s"}, 1000};
inline constexpr Quantity kAperture{
    {"--aperture", "", "code verifier: synthetic aperture"}, {0, 1.5, "modules"}, 0.5};
// The camera's own values are KEY=VALUE items of one option (marker/limits/camera_limits.hpp).
inline constexpr Text kCamera{
    {"--camera", "",
     "code reader's camera: KEY=VALUE,… (keys: pixel_um, f_number, defocus_um, falloff_pct, full_well_ke, "
     "read_noise_grey, seed, bare_reflectance, mark_reflectance, tone_ratio, grain_pct, …; docs/codes.md)"},
    {}, "a fixed-mount DPM reader's (docs/codes.md)"};
inline constexpr Choice kCodeReader{
    {"--reader", "", "code reader that decides"}, "zxing, libdmtx, zbar", {},
    "any two that read the symbology agree"};
// What the quality class's dose sufficiency measures the least-dosed stroke against.
inline constexpr Choice kDoseReference{
    {"--dose-reference", "",
     "quality: dose per mm judged against the pen's own power / speed, or against the material's need "
     "(full power at the speed where a single line marks one beam diameter wide, from --line-width at --line-speed)"},
    "pen, material", "pen"};
// What the read-back must grade (ISO/IEC TR 29158 overall grade).

inline constexpr SettingRef kCodeSettingList[] = {
    &kCodeEscapes, &kCodeSize,  &kModule,       &kBarHeight, &kMatrixSize,    &kMatrixShape,
    &kQrEcc,       &kQrVersion, &kModuleStyle,  &kDotShape,  &kDotSize,       &kCodeInvert,
    &kCodeX,       &kCodeY,     &kCodeAngle,    &kBeamDiameter, &kLineWidth,  &kLineSpeed,
    &kDoseReference, &kAperture, &kCamera,     &kCodeReader};
inline constexpr SettingTable kCodeSettings{"code", "Code", "objects[]", kCodeSettingList};

}  // namespace mark

#pragma once
// The settings of the scan head a job marks with: the preset, its simulated servo and laser
// rise, the spot and the field (one declaration each, setting.hpp). A job file names them at its
// top level ("head", "field_mm"); on the command line they are the --head options of every
// command that drives a head and the layout's --field.
#include "marker/limits/setting.hpp"

namespace mark {

// The presets of driver/sim/head_model.hpp (a test keeps this list equal to head_names()).
inline constexpr Text kHead{
    {"--head", "head",
     "scan head preset: SL10, SL14, cheap, SA14 (a job file may give {\"model\": …, \"spot_diameter_um\": …})"},
    "SL10"};
inline constexpr Choice kHeadModel{
    {"--head-model", "", "the simulated head's servo: first or second order"}, "first, second", {}, "the preset's"};
inline constexpr Quantity kHeadZeta{
    {"--head-zeta", "", "damping ζ of a second-order servo (--head-model second, or a second-order preset)"},
    {0.05, 10, ""}, {}, "the preset's"};
inline constexpr Quantity kLaserRise{
    {"--laser-rise-us", "", "laser power rise and fall time constant (0: instant)"}, {0, 1000, "µs"}, 0};
// The simulated head as it is, apart from the planner's model: its keys and their ranges are in
// plant_limits.hpp (parts of one value, like --camera's).
inline constexpr Text kPlant{
    {"--plant", "",
     "the simulated head as it is, apart from the planner's model: KEY=VALUE,… (keys: tau_scale, wn_scale, "
     "dead_us, latency_us, resonance_hz, resonance_zeta, accel_max, backemf_speed, rms_accel_pct, thermal_tau_s, current_tau_us, jerk_max, noise_um, seed, quant_bits; docs/speed.md)"},
    {}, "the preset itself"};
inline constexpr Quantity kSpot{
    {"--spot", "head.spot_diameter_um", "focused spot diameter (pulse overlap is measured against it)"},
    {1, 10000, "µm"}, 40};
// The largest field is a 10 m CNC table, the smallest a 1 mm micro-marking field; a laser head's
// field is at most the head's own (limited_range with the head's field_mm).
inline constexpr Quantity kField{
    {"--field", "field_mm", "field size (square; a scan head's at most its own field)"},
    {1, 10000, "mm"}, 110, "110; a job file: the head's (110)"};

// `head identify --from-image`: the picture's pixel on the part, from a microscope camera
// (0.1 µm) to the coarsest scan that still shows the pattern's 1 mm rows apart (1 mm).
inline constexpr Quantity kPicturePixel{
    {"--pixel-um", "", "head identify --from-image: the picture's pixel on the part"},
    {0.1, 1000, "µm"}, {}, "required with --from-image"};

inline constexpr SettingRef kHeadSettingList[] = {&kHead, &kHeadModel, &kHeadZeta, &kLaserRise,
                                                  &kPlant, &kSpot, &kField, &kPicturePixel};
inline constexpr SettingTable kHeadSettings{"head", "Head", "", kHeadSettingList};

}  // namespace mark

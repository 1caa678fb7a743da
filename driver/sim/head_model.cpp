// Head presets. Numbers from /work/shared/reference/dynamics.md (SCANLAB manuals, §1.2, §8);
// every figure below names its source.
//
// Field: 110 mm square at f = 160 mm (±0.34 rad optical; vendors sell "110 × 110" F160 fields).
// Speeds: field speed = optical angular speed × f (SCANLAB's own conversion), f = 160 mm.
// Tracking error τ: the preset values of dynamics.md §8 (SCANLAB datasheets, §1.2).
//
// Acceleration (per axis, in the field): a published figure where one exists, otherwise the
// least acceleration a datasheet step time implies. A move of d from rest to rest in time T
// needs at least a = 4·d/T² (bang-bang, no speed limit, no settling), so a head whose 10 %-of-
// full-scale step (11 mm here) settles in T accelerates at least that hard; we take that lower
// bound, so a planner trusting the preset never asks more of the mirrors than they can give:
//
//   preset  τ        v_max                   a_max        source of a_max
//   SL10    0.12 ms  19.2 m/s (120 rad/s)    4.4e7 mm/s²  basiCube 10: 10 %-FS step < 1.0 ms → 4·11/1.0² (the slower of the
//                                                         two 10 mm heads with the figure; SCANcube III 10's 0.85 ms gives 6.1e7)
//   SL14    0.21 ms  16.0 m/s (100 rad/s)    1.2e7 mm/s²  no 14 mm step time published; intelliSCAN 20's < 1.9 ms → 4·11/1.9²
//                                                         (a 20 mm mirror is heavier, so a 14 mm head does at least this)
//   cheap   0.25 ms   8.0 m/s ( 50 rad/s)    3.0e7 mm/s²  no budget-head datasheet; SCANcube 10 (SCANLAB's slowest 10 mm head,
//                                                         analog) 10 %-FS step 1.2 ms → 4·11/1.2² = 3.06e7, rounded down
//   SA14    0.21 ms  32.0 m/s (200 rad/s)    5.12e7 mm/s² excelliSCAN 14 (SCANahead): 320 000 rad/s² optical × 160 mm, 200 rad/s max
//
// SA14 is a feed-forward head of the excelliSCAN class: SCANLAB quotes zero tracking error for it
// because its controller pre-compensates the servo with a 1.2 ms preview. The servo's own loop
// behind that is not published; we model it as second order with intelliSCAN 14's ramp lag
// (0.21 ms, the same 14 mm aperture) and ζ = 0.7 (an assumed, typical servo tuning: 4.6 %
// overshoot). Its tracking error is zero only when the planner feeds forward an identified model
// of it (marker head identify); the datasheet's jump times (1 / 10 / 100 mm in 0.28 / 0.88 /
// 3.75 ms) are exactly a trapezoid with its two limits.
//
// SL10 uses 120 rad/s (SCANcube III 10's typical positioning speed) rather than the 150 rad/s
// maximum. SL14: intelliSCAN 14's maximum, 100 rad/s. cheap: τ from the LightBurn users'
// TCON/TCOFF calibration read through SCANLAB's 0.6τ/1.2τ rule (τ ≈ 0.20–0.26 ms); 50 rad/s,
// the lowest maximum in the SCANLAB table (intelliSCAN 30), near SCANcube 10's typical 45 rad/s.
//
// With these (lower) accelerations the simulated step responses are slower than the datasheets'
// (tests/driver/sim_validation_test.cpp gives the figures): the presets err on the safe side.
#include "driver/sim/head_model.hpp"

#include <algorithm>
#include <cctype>

namespace mark {
namespace {

constexpr double focal_mm = 160;

HeadModel make(const char* name, double tau_s, double speed_rad_s, double accel_mm_s2) {
  HeadModel h;
  h.name = name;
  h.tau_s = tau_s;
  h.max_speed_mm_s = speed_rad_s * focal_mm;
  h.max_accel_mm_s2 = accel_mm_s2;
  h.field_mm = 110;
  return h;
}

bool equal_nocase(std::string_view a, std::string_view b) {
  return a.size() == b.size() && std::equal(a.begin(), a.end(), b.begin(), [](char x, char y) {
           return std::tolower(static_cast<unsigned char>(x)) ==
                  std::tolower(static_cast<unsigned char>(y));
         });
}

}  // namespace

HeadModel head_sl10() { return make("SL10", 0.12e-3, 120, 4.4e7); }
HeadModel head_sl14() { return make("SL14", 0.21e-3, 100, 1.2e7); }
HeadModel head_cheap() { return make("cheap", 0.25e-3, 50, 3.0e7); }
HeadModel head_sa14() {
  HeadModel h = make("SA14", 0.21e-3, 200, 320000 * focal_mm);
  h.second_order = true;
  h.zeta = 0.7;
  return h;
}

std::optional<HeadModel> find_head(std::string_view name) {
  for (HeadModel h : {head_sl10(), head_sl14(), head_cheap(), head_sa14()})
    if (equal_nocase(h.name, name)) return h;
  return std::nullopt;
}

std::vector<std::string> head_names() { return {"SL10", "SL14", "cheap", "SA14"}; }

}  // namespace mark

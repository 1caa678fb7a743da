#pragma once
// Scan-head presets for the simulated scanner: tracking error τ (first-order lag, or the ramp lag
// of a second-order servo), positioning speed and acceleration limits, field size. Where every
// number comes from is in head_model.cpp.
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace mark {

struct HeadModel {
  std::string name;
  double tau_s = 0.12e-3;            // tracking error: time lag at constant speed
  double max_speed_mm_s = 24000;     // per-axis positioning speed limit
  double max_accel_mm_s2 = 1e8;      // per-axis acceleration limit
  double field_mm = 110;             // square field, centred on 0: |x|, |y| ≤ field_mm / 2
  bool second_order = false;         // false: first-order lag; true: (ωn, ζ) with ωn = 2ζ/τ
  double zeta = 1.0;                 // damping of the second-order model
  // Focused spot diameter (1/e²): pulses closer than this overlap into a line (dynamics.md §4.2:
  // ≈ 40 µm at f = 160 mm with a 7 mm beam and M² = 1.3).
  double spot_diameter_um = 40;

  // Natural frequency of the second-order model with the same ramp lag τ (rad/s).
  double omega_n() const { return 2 * zeta / tau_s; }
  // Longest command period the head follows smoothly: SCANLAB's rule, ≤ 20 % of τ.
  double max_tick_s() const { return 0.2 * tau_s; }
  double half_field_mm() const { return field_mm / 2; }
};

HeadModel head_sl10();   // SCANLAB 10 mm class, τ = 0.12 ms
HeadModel head_sl14();   // SCANLAB 14 mm class, τ = 0.21 ms
HeadModel head_cheap();  // BJJCZ-driven budget head, τ = 0.25 ms
HeadModel head_sa14();   // excelliSCAN 14 class (SCANahead limits), second-order servo, τ = 0.21 ms

// Preset by name ("SL10", "SL14", "cheap", "SA14"; case-insensitive), or nothing.
std::optional<HeadModel> find_head(std::string_view name);
// Names find_head() knows, for help texts and errors.
std::vector<std::string> head_names();

}  // namespace mark

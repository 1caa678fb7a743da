#pragma once
// A head profile: what the planner knows about a scan head — its servo model (first order: τ;
// second order: ωn, ζ) and its speed and acceleration limits, measured by `marker head identify`
// or taken from a datasheet. The planner feeds this model forward and plans within these
// limits; it never reads the simulator's own parameters.
//
// File format (JSON, docs/speed.md): every number names its unit in its key.
//   { "format": "marker head profile", "version": 1, "head": "SL10", "model": "first",
//     "tau_s": 1.2e-4, "omega_n_rad_s": 1.7e4, "zeta": 1.02,
//     "max_speed_mm_s": 19200, "max_accel_mm_s2": 4.4e7, "field_mm": 110, "tick_s": 1e-5,
//     "fit_rms_first_um": 0.01, "fit_rms_second_um": 0.01, "source": "identified" }
//   and, when a picture showed one, "resonance_hz": 9950, "resonance_zeta": 0.02.
#include <string>
#include <string_view>

#include "driver/sim/head_model.hpp"

namespace mark {

enum class ServoOrder { first, second };

std::string_view to_string(ServoOrder order);
// "first" or "second"; throws InputError naming the value otherwise.
ServoOrder parse_servo_order(std::string_view name);

struct HeadProfile {
  std::string head;                  // the head it describes (preset or machine name)
  ServoOrder model = ServoOrder::first;  // the fit the planner feeds forward
  double tau_s = 0;                  // first-order fit: tracking error (ramp lag)
  double omega_n_rad_s = 0;          // second-order fit: natural frequency
  double zeta = 0;                   // second-order fit: damping
  double max_speed_mm_s = 0;         // per axis
  double max_accel_mm_s2 = 0;        // per axis
  double field_mm = 0;
  double tick_s = 10e-6;             // command period the head was measured at
  double fit_rms_first_um = 0;       // residual of each fit over the linear test parts
  double fit_rms_second_um = 0;
  // A mirror resonance the identification saw ringing after the test pattern's corners (0 Hz:
  // none seen): a planner that looks ahead shapes its locus against it (input_shaper.hpp).
  double resonance_hz = 0;
  double resonance_zeta = 0;
  std::string source = "identified";  // "identified" (measured) or "datasheet"

  // Ramp lag of the chosen model: τ, or 2ζ/ωn.
  double lag_s() const;
  // The second-order term of the inverse filter x_cmd = x + lag·ẋ + inertia·ẍ: 1/ωn² for the
  // second-order model, 0 for the first-order one.
  double inertia_s2() const;
  // The same profile with its model's time constants scaled by (1 + error): τ·(1+e), and for
  // the second order ωn/(1+e), so the ramp lag is off by the same share (cps's model-error rows).
  HeadProfile with_lag_error(double error) const;
};

// What a datasheet says, without measuring: the preset's τ (or ωn, ζ) and limits. For `mark`
// without a profile file; cps and the tests use identified profiles.
HeadProfile datasheet_profile(const HeadModel& head);

// JSON text of a profile (one object, pretty-printed) and back. parse_head_profile throws
// InputError naming `where` (a file name), the key and the allowed range on any bad input.
std::string head_profile_json(const HeadProfile& profile);
HeadProfile parse_head_profile(std::string_view json_text, std::string_view where);

// Files: written to a temporary name and renamed, so a reader never sees half a profile.
void save_head_profile(const HeadProfile& profile, const std::string& path);
HeadProfile load_head_profile(const std::string& path);

}  // namespace mark

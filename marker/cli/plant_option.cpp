#include "marker/cli/plant_option.hpp"

#include <vector>

#include "base/error.hpp"
#include "marker/cli/number_keys.hpp"
#include "marker/cli/option_values.hpp"
#include "marker/limits/plant_limits.hpp"

namespace mark::cli {
namespace {

// One --plant key: the value as typed (in the key's unit) ↔ the Plant field (SI where it is).
struct PlantKey {
  NumberKey key;
  void (*set)(Plant&, double);
  double (*get)(const Plant&);
  const char* help;
};

const std::vector<PlantKey>& plant_keys() {
  static const std::vector<PlantKey> keys{
      {{"tau_scale", &kPlantTauScaleRange}, [](Plant& p, double v) { p.tau_scale = v; },
       [](const Plant& p) { return p.tau_scale; }, "the servo's ramp lag τ × this (second order: ωn ÷ this)"},
      {{"wn_scale", &kPlantWnScaleRange}, [](Plant& p, double v) { p.wn_scale = v; },
       [](const Plant& p) { return p.wn_scale; },
       "second-order servo: ωn × this at the same ramp lag (ζ × this); a first-order servo ignores it"},
      {{"dead_us", &kPlantDeadRange}, [](Plant& p, double v) { p.dead_us = v; },
       [](const Plant& p) { return p.dead_us; },
       "servo dead time inside the loop: it acts on the position as it was this long ago (1 µs steps)"},
      {{"latency_us", &kPlantDeadRange}, [](Plant& p, double v) { p.latency_us = v; },
       [](const Plant& p) { return p.latency_us; },
       "command latency outside the loop: the response shifted this much later (1 µs steps; the laser is not)"},
      {{"resonance_hz", &kPlantResonanceRange}, [](Plant& p, double v) { p.resonance_hz = v; },
       [](const Plant& p) { return p.resonance_hz; }, "mirror resonance against the motor shaft (0: none)"},
      {{"resonance_zeta", &kPlantResonanceZetaRange}, [](Plant& p, double v) { p.resonance_zeta = v; },
       [](const Plant& p) { return p.resonance_zeta; }, "damping of the mirror resonance"},
      {{"accel_max", &kPlantAccelRange}, [](Plant& p, double v) { p.accel_max_mm_s2 = v; },
       [](const Plant& p) { return p.accel_max_mm_s2; }, "the mirror's acceleration limit, mm/s² (0: the preset's)"},
      {{"backemf_speed", &kPlantBackEmfRange}, [](Plant& p, double v) { p.backemf_speed_mm_s = v; },
       [](const Plant& p) { return p.backemf_speed_mm_s; },
       "back-EMF, mm/s: speeding up, the acceleration left is a_max·(1 − |v| / this); braking keeps a_max (0: none)"},
      {{"rms_accel_pct", &kPlantRmsAccelRange}, [](Plant& p, double v) { p.rms_accel_pct = v; },
       [](const Plant& p) { return p.rms_accel_pct; },
       "thermal limit: the drive trips (laser off, job failed) when an axis's rms acceleration over thermal_tau_s passes this % of its peak (0: none)"},
      {{"thermal_tau_s", &kPlantThermalTauRange}, [](Plant& p, double v) { p.thermal_tau_s = v; },
       [](const Plant& p) { return p.thermal_tau_s; }, "the coils' thermal time constant, s (the rms window)"},
      {{"current_tau_us", &kPlantCurrentTauRange}, [](Plant& p, double v) { p.current_tau_us = v; },
       [](const Plant& p) { return p.current_tau_us; },
       "the amplifier's current loop lag: the acceleration follows the servo's demand this late; corners and jumps ring (0: none)"},
      {{"jerk_max", &kPlantJerkRange}, [](Plant& p, double v) { p.jerk_max_mm_s3 = v; },
       [](const Plant& p) { return p.jerk_max_mm_s3; },
       "with current_tau_us: the current's slew (supply voltage over coil inductance) as a jerk limit, mm/s³ (0: none)"},
      {{"noise_um", &kPlantNoiseRange}, [](Plant& p, double v) { p.noise_um = v; },
       [](const Plant& p) { return p.noise_um; }, "beam position noise, rms per axis, correlated over the servo's τ"},
      {{"seed", &kPlantSeedRange, true}, [](Plant& p, double v) { p.seed = static_cast<std::uint64_t>(v); },
       [](const Plant& p) { return static_cast<double>(p.seed); }, "noise seed (the same seed gives the same figures)"},
      {{"quant_bits", &kPlantQuantRange, true}, [](Plant& p, double v) { p.quant_bits = static_cast<int>(v); },
       [](const Plant& p) { return static_cast<double>(p.quant_bits); },
       "command quantisation: 2^bits codes across the field (XY2-100: 16; 0: exact)"},
  };
  return keys;
}

}  // namespace

Plant parse_plant_option(const std::string& text) {
  Plant p;
  const auto& keys = plant_keys();
  std::vector<NumberKey> names;
  for (const PlantKey& k : keys) names.push_back(k.key);
  for (const auto& [k, v] : parse_number_keys("--plant", text, names, "tau_scale=1.1,dead_us=10"))
    keys[k].set(p, v);
  if (p.jerk_max_mm_s3 > 0 && p.current_tau_us == 0)
    throw InputError("--plant jerk_max: the jerk limit is the current loop's slew; give current_tau_us too");
  return p;
}

std::string plant_text(const Plant& plant) {
  std::string out;
  const Plant model;
  for (const PlantKey& k : plant_keys())
    if (k.get(plant) != k.get(model)) {
      if (!out.empty()) out += ',';
      out.append(k.key.name).append("=").append(exact_number(k.get(plant)));
    }
  return out;
}

std::string plant_keys_help() {
  std::string out;
  const Plant model;
  for (const PlantKey& k : plant_keys())
    out.append(k.key.name).append(" (").append(k.key.range->text()).append(", default ")
        .append(format_number(k.get(model))).append("): ").append(k.help).append("\n");
  return out;
}

}  // namespace mark::cli

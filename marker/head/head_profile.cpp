#include "marker/head/head_profile.hpp"

#include <cmath>
#include <nlohmann/json.hpp>

#include "base/error.hpp"
#include "marker/limits/pen_settings.hpp"
#include "marker/head/head_file.hpp"
#include "marker/output/output_file.hpp"

namespace mark {
namespace {

constexpr const char* kFormat = "marker head profile";
constexpr int kVersion = 1;

// Allowed ranges: wide enough for any galvo (a τ from microseconds to 0.1 s, speeds to
// 1000 m/s), narrow enough that a typo or a unit mix-up (ms for s) is refused.
struct Range {
  const char* key;
  double lo, hi;
};
constexpr Range kTau{"tau_s", 1e-7, 0.1};
constexpr Range kOmega{"omega_n_rad_s", 1.0, 1e8};
constexpr Range kZeta{"zeta", 1e-3, 100};
constexpr Range kSpeed{"max_speed_mm_s", 1e-3, 1e6};
constexpr Range kAccelRange{"max_accel_mm_s2", 1e-3, 1e12};
constexpr Range kField{"field_mm", 1e-3, 1e4};
constexpr Range kTickRange{"tick_s", 1e-7, 1e-2};
constexpr Range kRms{"", 0, 1e9};
// A resonance a pen's shaper takes (the shaper settings' bounds).
constexpr Range kResonance{"resonance_hz", kShaperHz.bounds.min, kShaperHz.bounds.max};
constexpr Range kResonanceZeta{"resonance_zeta", kShaperZeta.bounds.min, kShaperZeta.bounds.max};

constexpr HeadFileKind kKind{"head profile", kFormat, kVersion};

double number(const nlohmann::json& j, const char* key, const Range& r, std::string_view where,
              bool required = true, double fallback = 0) {
  return head_file_number(kKind, j, key, r.lo, r.hi, where, required, fallback);
}

std::string text(const nlohmann::json& j, const char* key, std::string_view where,
                 const std::string& fallback) {
  const auto it = j.find(key);
  if (it == j.end()) return fallback;
  if (!it->is_string()) head_file_error(kKind, where, std::string("'") + key + "' must be a string");
  return it->get<std::string>();
}

}  // namespace

std::string_view to_string(ServoOrder order) {
  return order == ServoOrder::first ? "first" : "second";
}

ServoOrder parse_servo_order(std::string_view name) {
  if (name == "first") return ServoOrder::first;
  if (name == "second") return ServoOrder::second;
  throw InputError("head model '" + std::string(name) + "' is not one of first, second");
}

double HeadProfile::lag_s() const {
  return model == ServoOrder::first ? tau_s : 2 * zeta / omega_n_rad_s;
}

double HeadProfile::inertia_s2() const {
  return model == ServoOrder::first ? 0.0 : 1.0 / (omega_n_rad_s * omega_n_rad_s);
}

HeadProfile HeadProfile::with_lag_error(double error) const {
  HeadProfile p = *this;
  p.tau_s *= 1 + error;
  p.omega_n_rad_s /= 1 + error;
  return p;
}

HeadProfile datasheet_profile(const HeadModel& head) {
  HeadProfile p;
  p.head = head.name;
  p.model = head.second_order ? ServoOrder::second : ServoOrder::first;
  p.tau_s = head.tau_s;
  p.omega_n_rad_s = head.omega_n();
  p.zeta = head.zeta;
  p.max_speed_mm_s = head.max_speed_mm_s;
  p.max_accel_mm_s2 = head.max_accel_mm_s2;
  p.field_mm = head.field_mm;
  p.source = "datasheet";
  return p;
}

std::string head_profile_json(const HeadProfile& p) {
  nlohmann::ordered_json j;
  j["format"] = kFormat;
  j["version"] = kVersion;
  j["head"] = p.head;
  j["model"] = to_string(p.model);
  j["tau_s"] = p.tau_s;
  j["omega_n_rad_s"] = p.omega_n_rad_s;
  j["zeta"] = p.zeta;
  j["max_speed_mm_s"] = p.max_speed_mm_s;
  j["max_accel_mm_s2"] = p.max_accel_mm_s2;
  j["field_mm"] = p.field_mm;
  j["tick_s"] = p.tick_s;
  j["fit_rms_first_um"] = p.fit_rms_first_um;
  j["fit_rms_second_um"] = p.fit_rms_second_um;
  if (p.resonance_hz > 0) {
    j["resonance_hz"] = p.resonance_hz;
    j["resonance_zeta"] = p.resonance_zeta;
  }
  j["source"] = p.source;
  return j.dump(2) + "\n";
}

HeadProfile parse_head_profile(std::string_view json_text, std::string_view where) {
  const nlohmann::json j = parse_head_file(kKind, json_text, where);
  HeadProfile p;
  p.head = text(j, "head", where, "");
  const std::string model = text(j, "model", where, "first");
  if (model != "first" && model != "second")
    head_file_error(kKind, where, "'model' is \"" + model + "\", not one of first, second");
  p.model = parse_servo_order(model);
  // The chosen model's parameters are required, the other's optional.
  const bool first = p.model == ServoOrder::first;
  p.tau_s = number(j, kTau.key, kTau, where, first);
  p.omega_n_rad_s = number(j, kOmega.key, kOmega, where, !first);
  p.zeta = number(j, kZeta.key, kZeta, where, !first);
  p.max_speed_mm_s = number(j, kSpeed.key, kSpeed, where);
  p.max_accel_mm_s2 = number(j, kAccelRange.key, kAccelRange, where);
  p.field_mm = number(j, kField.key, kField, where);
  p.tick_s = number(j, kTickRange.key, kTickRange, where, false, 10e-6);
  p.fit_rms_first_um = number(j, "fit_rms_first_um", kRms, where, false);
  p.fit_rms_second_um = number(j, "fit_rms_second_um", kRms, where, false);
  p.resonance_hz = number(j, kResonance.key, kResonance, where, false);
  p.resonance_zeta = number(j, kResonanceZeta.key, kResonanceZeta, where, false);
  p.source = text(j, "source", where, "identified");
  return p;
}

void save_head_profile(const HeadProfile& profile, const std::string& path) {
  write_file_whole(path, head_profile_json(profile));
}

HeadProfile load_head_profile(const std::string& path) {
  return parse_head_profile(read_head_file(kKind, path), path);
}

}  // namespace mark

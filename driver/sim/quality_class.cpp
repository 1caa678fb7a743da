#include "driver/sim/quality_class.hpp"

#include <cstdio>

namespace mark {

std::string_view to_string(QualityClass c) {
  switch (c) {
    case QualityClass::poor: return "poor";
    case QualityClass::good: return "good";
    case QualityClass::high: return "high";
  }
  return "?";
}

std::optional<QualityClass> parse_quality_class(std::string_view name) {
  for (QualityClass c : {QualityClass::poor, QualityClass::good, QualityClass::high})
    if (name == to_string(c)) return c;
  return std::nullopt;
}

std::string quality_figures(const Quality& q) {
  char dose[64];
  if (q.dose_ratio_max >= 1e9)
    std::snprintf(dose, sizeof dose, "most of the strokes got no dose");
  else
    std::snprintf(dose, sizeof dose, "dose ratio %.2f", q.dose_ratio_max);
  char gap[80] = "";
  if (q.spot_diameter_um > 0)
    std::snprintf(gap, sizeof gap, ", pulse gap %.1f µm (spot %.0f µm)", q.pulse_gap_max_um, q.spot_diameter_um);
  char s[320];
  std::snprintf(s, sizeof s, "max deviation %.1f µm, coverage %.2f %%, %s%s, dose per mm %.0f %% of the %s",
                q.max_deviation_um, 100 * q.coverage, dose, gap, 100 * q.dose_per_mm_fraction,
                q.dose_vs_material ? "material's" : "pen's");
  return s;
}

}  // namespace mark

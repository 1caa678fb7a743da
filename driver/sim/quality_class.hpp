#pragma once
// Quality classes of a mark, SCANLAB's two cps levels made measurable on the simulated beam:
// "high" (no visible defect) and "good" (slight corner rounding or burn-in allowed); anything
// worse is "poor". `cps` searches for the fastest marking that meets a class, `mark` reports the
// class of every mark and can refuse to fire below one (--require-quality).
#include <optional>
#include <string>
#include <string_view>

#include "driver/sim/quality.hpp"

namespace mark {

enum class QualityClass { poor, good, high };

struct QualityLimits {
  QualityClass level;
  double max_deviation_um;  // at most
  double min_coverage;      // at least (fraction of the intended stroke length)
  double max_dose_ratio;    // at most (burn-in: max / median dose along the strokes)
  // Line continuity: the widest centre-line gap between consecutive pulse spots, at most this
  // share of the spot diameter.
  double max_pulse_gap_share;
  // Dose sufficiency: the least-dosed stroke's energy per mm, at least this share of the pen's
  // nominal (power / marking speed), or of the material's (MarkIntent::dose_vs_material).
  double min_dose_per_mm_fraction;
};

// Why these limits:
// - Pulses. "high" is a line with no visible defect: the spots of consecutive pulses must touch
//   (gap 0, spacing ≤ spot diameter). "good" allows gaps up to half a spot: the spots (pulse
//   spacing ≤ 1.5 diameters) still cover two thirds of the centre line, a dotted line that reads
//   as one, as ISO/IEC TR 29158 grades dot-marked symbols after closing gaps of that order;
//   beyond it the dots stand apart.
// - Dose. On the simulated material (mark_response.hpp: the line is one spot wide at the
//   nominal energy per mm), a line at 80 % of it is 94 % as wide, at 50 % 81 %
//   (w(f)/w(1) = √(1 + ln f / 2)): "high" keeps the stroke width within 6 % of what the pen was
//   set up for, "good" within a fifth. Below, strokes visibly thin and then vanish (at 13.5 %).
inline constexpr QualityLimits kHighQuality{QualityClass::high, 10, 0.995, 1.3, 0.0, 0.8};
inline constexpr QualityLimits kGoodQuality{QualityClass::good, 30, 0.98, 2.0, 0.5, 0.5};

inline bool meets(const Quality& q, const QualityLimits& l) {
  return q.lit_points > 0 && q.max_deviation_um <= l.max_deviation_um &&
         q.coverage >= l.min_coverage && q.dose_ratio_max <= l.max_dose_ratio &&
         q.pulse_gap_max_um <= l.max_pulse_gap_share * q.spot_diameter_um &&
         q.dose_per_mm_fraction >= l.min_dose_per_mm_fraction;
}

inline QualityClass classify(const Quality& q) {
  if (meets(q, kHighQuality)) return QualityClass::high;
  if (meets(q, kGoodQuality)) return QualityClass::good;
  return QualityClass::poor;
}

std::string_view to_string(QualityClass c);
// "high", "good" or "poor"; nothing otherwise.
std::optional<QualityClass> parse_quality_class(std::string_view name);

// The figures a class is decided on, for messages: "max deviation 55.0 µm, coverage 97.00 %,
// dose ratio 1.67, pulse gap 60.0 µm (spot 40 µm), dose per mm 31 % of the pen's". With most of the strokes unlit the dose ratio's median is 0 and its value a
// sentinel (quality.hpp): the words say so instead of printing 1000000000.00.
std::string quality_figures(const Quality& q);

}  // namespace mark

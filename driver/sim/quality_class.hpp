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
};

inline constexpr QualityLimits kHighQuality{QualityClass::high, 10, 0.995, 1.3};
inline constexpr QualityLimits kGoodQuality{QualityClass::good, 30, 0.98, 2.0};

inline bool meets(const Quality& q, const QualityLimits& l) {
  return q.lit_points > 0 && q.max_deviation_um <= l.max_deviation_um &&
         q.coverage >= l.min_coverage && q.dose_ratio_max <= l.max_dose_ratio;
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
// dose ratio 1.67". With most of the strokes unlit the dose ratio's median is 0 and its value a
// sentinel (quality.hpp): the words say so instead of printing 1000000000.00.
std::string quality_figures(const Quality& q);

}  // namespace mark

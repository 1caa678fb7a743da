#include "marker/cnc/cut_settings.hpp"

#include <cmath>
#include <sstream>
#include <string>

#include "base/error.hpp"

namespace mark {
namespace {

constexpr int kMaxPasses = 10000;

void require_positive(double v, const char* name) {
  if (!(v > 0) || !std::isfinite(v)) {
    std::ostringstream m;
    m << name << " must be a positive number of millimetres, got " << v;
    throw InputError(m.str());
  }
}

}  // namespace

void validate(const CutSettings& s) {
  require_positive(s.tool_diameter_mm, "tool diameter");
  require_positive(s.depth_mm, "depth");
  if (!(s.depth_per_pass_mm >= 0) || !std::isfinite(s.depth_per_pass_mm))
    throw InputError("depth per pass must be 0 (one pass) or positive, got " +
                     std::to_string(s.depth_per_pass_mm));
  require_positive(s.safe_z_mm, "safe Z");
  require_positive(s.feed_mm_min, "feed (mm/min)");
  require_positive(s.plunge_feed_mm_min, "plunge feed (mm/min)");
  require_positive(s.arcs.tolerance_mm, "arc tolerance");
  if (s.depth_per_pass_mm > 0 && s.depth_mm / s.depth_per_pass_mm > kMaxPasses)
    throw InputError("depth " + std::to_string(s.depth_mm) + " mm at " +
                     std::to_string(s.depth_per_pass_mm) + " mm per pass needs more than " +
                     std::to_string(kMaxPasses) + " passes");
}

std::vector<double> pass_depths(const CutSettings& s) {
  const int passes = s.depth_per_pass_mm > 0
                         ? std::max(1, static_cast<int>(std::ceil(s.depth_mm / s.depth_per_pass_mm - 1e-9)))
                         : 1;
  std::vector<double> z;
  for (int k = 1; k <= passes; ++k) z.push_back(-s.depth_mm * k / passes);
  return z;
}

}  // namespace mark

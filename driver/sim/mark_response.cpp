#include "driver/sim/mark_response.hpp"
#include "driver/sim/param_range.hpp"

#include <cmath>
#include <numbers>
#include <stdexcept>

namespace mark {
namespace {

double peak(double speed_mm_s, double w) { return std::sqrt(2 / std::numbers::pi) / (w * speed_mm_s); }

void require(const char* what, double v, double lo, double hi, const char* unit) {
  require_param_range("", what, v, lo, hi, unit);
}

}  // namespace

double MarkResponse::threshold_s_mm2() const {
  const double w = beam_radius_mm(), r = reference_width_mm / 2;
  return peak(reference_speed_mm_s, w) * std::exp(-2 * r * r / (w * w));
}

double MarkResponse::line_width_mm(double speed_mm_s) const {
  const double w = beam_radius_mm();
  const double ratio = peak(speed_mm_s, w) / threshold_s_mm2();
  return ratio <= 1 ? 0.0 : 2 * w * std::sqrt(std::log(ratio) / 2);
}

double MarkResponse::vanishing_speed_mm_s() const {
  return std::sqrt(2 / std::numbers::pi) / (beam_radius_mm() * threshold_s_mm2());
}

// The width is one diameter where the peak is e² times the threshold (line_width_mm), and the
// peak falls as 1/speed.
double MarkResponse::spot_line_speed_mm_s() const { return vanishing_speed_mm_s() / std::exp(2.0); }

void check_mark_response(const MarkResponse& r) {
  require("spot diameter", r.spot_diameter_mm, 0.001, 5, "mm");
  require("reference speed", r.reference_speed_mm_s, 1, 100000, "mm/s");
  require("reference line width", r.reference_width_mm, 0.001, 3 * r.spot_diameter_mm, "mm");
}

}  // namespace mark

#include "marker/plan/settle_model.hpp"

#include <algorithm>
#include <cmath>

namespace mark {

double transient_mm(const Point& v_before, const Point& v_move, double t_move_s,
                    const Point& v_after, double tau_s) {
  return tau_s * ((v_move - v_before) * std::exp(-t_move_s / tau_s) + (v_after - v_move)).norm();
}

double settle_time_s(double amplitude_mm, double settle_mm, double tau_s) {
  return amplitude_mm > settle_mm ? tau_s * std::log(amplitude_mm / settle_mm) : 0.0;
}

double settled_run_in_mm(const RunInRequest& r) {
  if (!(r.tau_s > 0) || !(r.settle_mm > 0)) return r.min_length_mm;
  const double vt = r.speed_mm_s * r.tau_s;  // mm per multiple k
  const double k_min = r.min_length_mm / vt;
  const Point v_in = r.speed_mm_s * r.direction;
  double k = k_min;
  for (int it = 0; it < 8; ++it) {
    const Point d = (r.start - k * vt * r.direction) - r.from;
    const double dist = d.norm();
    const Point v_join = dist > 0 ? Point(r.join_speed_mm_s / dist * d) : Point(0, 0);
    const double t_join = dist > 0 ? dist / r.join_speed_mm_s : 0.0;
    const double a = transient_mm(r.velocity_mm_s, v_join, t_join, v_in, r.tau_s);
    // The laser switches on τ after the run-in ends: k·τ + τ of decay in all.
    const double k_new = std::max(k_min, settle_time_s(a, r.settle_mm, r.tau_s) / r.tau_s - 1.0);
    const bool done = std::abs(k_new - k) < 1e-2;  // the run-in is rounded up to ticks anyway
    k = k_new;
    if (done) break;
  }
  return k * vt;
}

}  // namespace mark

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
  // The transient left when the laser switches on after a run-in of k·v·τ: the join's A, decayed
  // over the run-in (k·τ) and the laser's τ delay.
  const auto left_mm = [&](double k) {
    const Point d = (r.start - k * vt * r.direction) - r.from;
    const double dist = d.norm();
    const Point v_join = dist > 0 ? Point(r.join_speed_mm_s / dist * d) : Point(0, 0);
    const double t_join = dist > 0 ? dist / r.join_speed_mm_s : 0.0;
    return transient_mm(r.velocity_mm_s, v_join, t_join, v_in, r.tau_s) * std::exp(-(k + 1));
  };
  // Steps of 0.05 v·τ, then the step that settles halved down to 1e-4 v·τ; A is at most a few
  // (jump speed + v)·τ, so ln(A/ε) bounds the search well below k_min + 40.
  constexpr double kStep = 0.05, kSpan = 40;
  if (left_mm(k_min) <= r.settle_mm) return k_min * vt;
  for (double k = k_min + kStep; k < k_min + kSpan; k += kStep) {
    if (left_mm(k) > r.settle_mm) continue;
    double lo = k - kStep, hi = k;  // lo leaves too much, hi settles
    while (hi - lo > 1e-4) {
      const double mid = (lo + hi) / 2;
      (left_mm(mid) <= r.settle_mm ? hi : lo) = mid;
    }
    return hi * vt;
  }
  return (k_min + kSpan) * vt;
}

}  // namespace mark

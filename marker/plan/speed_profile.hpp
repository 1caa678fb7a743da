#pragma once
// The speed along one planned command: a trapezoid in time. It starts at v0, speeds up at a to
// the peak vp, cruises, and slows down at d to v1 at the end of the path (length L); when L is
// too short to reach the command's speed the cruise has zero length (a triangle). Everything
// here is closed-form, so the locus generator evaluates it per sample without iteration.
#include <algorithm>
#include <cmath>

namespace mark {

struct SpeedProfile {
  double length = 0;     // mm
  double v0 = 0, vp = 0, v1 = 0;  // entry, peak, exit speed (mm/s)
  double a = 0, d = 0;   // acceleration and deceleration (mm/s², both > 0)
  double t1 = 0, t2 = 0, duration = 0;  // end of the rise, end of the cruise, end (s)
  double s1 = 0, s2 = 0;  // path length at t1 and at t2

  // The profile of a path of `length` entered at v0, left at v1, limited to `cruise`, with
  // rates a and d. v0 and v1 must be reachable (the look-ahead planner guarantees it:
  // |v1² − v0²| ≤ 2·rate·length); they are clamped to `cruise`.
  static SpeedProfile make(double length, double v0, double v1, double cruise, double a, double d) {
    SpeedProfile p;
    p.length = length;
    p.a = a;
    p.d = d;
    p.v0 = std::min(v0, cruise);
    p.v1 = std::min(v1, cruise);
    // Peak of the triangle: v0² + 2a·s = vp² = v1² + 2d·(L − s).
    const double tri = std::sqrt(std::max(0.0, (2 * a * d * length + d * p.v0 * p.v0 + a * p.v1 * p.v1) / (a + d)));
    p.vp = std::max({std::min(cruise, tri), p.v0, p.v1});
    p.s1 = (p.vp * p.vp - p.v0 * p.v0) / (2 * a);
    const double s_down = (p.vp * p.vp - p.v1 * p.v1) / (2 * d);
    p.s2 = std::max(p.s1, length - s_down);
    p.t1 = (p.vp - p.v0) / a;
    p.t2 = p.t1 + (p.vp > 0 ? (p.s2 - p.s1) / p.vp : 0.0);
    p.duration = p.t2 + (p.vp - p.v1) / d;
    return p;
  }

  // Path length, speed and tangential acceleration at time t ∈ [0, duration].
  double position(double t) const {
    if (t <= t1) return v0 * t + 0.5 * a * t * t;
    if (t <= t2) return s1 + vp * (t - t1);
    const double u = std::min(t, duration) - t2;
    return std::min(length, s2 + vp * u - 0.5 * d * u * u);
  }
  double speed(double t) const {
    if (t <= t1) return v0 + a * t;
    if (t <= t2) return vp;
    return std::max(v1, vp - d * (std::min(t, duration) - t2));
  }
  double accel(double t) const {
    if (t < t1) return a;
    if (t <= t2) return 0;
    return t < duration ? -d : 0;
  }
};

}  // namespace mark

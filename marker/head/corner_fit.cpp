#include "marker/head/corner_fit.hpp"

#include <algorithm>
#include <cmath>

#include "base/error.hpp"
#include "driver/sim/second_order_step.hpp"

namespace mark {
namespace {

constexpr double kModelStep_s = 1e-6;
constexpr double kFromCorner_mm = 0.15;  // clear of the first leg's ink
constexpr double kBeforeEnd_mm = 0.3;    // clear of the second leg's lagging end
constexpr double kLegWindow_mm = 0.35;   // across the second leg, about its settled centre
constexpr double kFindWindow_mm = 0.8;   // where a leg is looked for about its place in the box

// One axis of the servo: first order at ramp lag τ, or second order (ωn, ζ) with ramp lag 2ζ/ωn.
struct AxisServo {
  bool second = false;
  double tau = 0;
  SecondOrderStep step;

  AxisServo(double tau_s, double zeta) : second(zeta > 0), tau(tau_s) {
    if (second) step = second_order_step(2 * zeta / tau_s, zeta, kModelStep_s);
  }
  // One step towards the command c (at the step's start) moving at `rate`.
  void advance(double& x, double& v, double c, double rate) const {
    if (second) return step.apply(x, v, c, rate);
    const double settled = c - tau * rate;  // the steady ramp's place at the step's start
    const double decay = std::exp(-kModelStep_s / tau);
    x = settled + rate * kModelStep_s + (x - settled) * decay;
  }
};

// The model's corner: the stopping axis's place (relative to the corner, + past it) as the
// running axis passes each place along the second leg. Both from rest at the first leg's start.
struct ModelCorner {
  std::vector<double> run, stop, t;  // t: time since the command turned the corner, s

  double stop_at(double run_mm) const { return at(stop, run_mm); }
  double time_at(double run_mm) const { return at(t, run_mm); }

 private:
  double at(const std::vector<double>& of, double run_mm) const {
    const auto it = std::lower_bound(run.begin(), run.end(), run_mm);
    if (it == run.begin()) return of.front();
    if (it == run.end()) return of.back();
    const auto i = static_cast<std::size_t>(it - run.begin());
    const double f = (run_mm - run[i - 1]) / (run[i] - run[i - 1]);
    return of[i - 1] + f * (of[i] - of[i - 1]);
  }
};

ModelCorner model_corner(double leg_mm, double v, const AxisServo& stop_axis, const AxisServo& run_axis) {
  const auto n = static_cast<std::size_t>(std::lround(leg_mm / v / kModelStep_s));
  double s = -leg_mm, sv = 0, r = 0, rv = 0;
  for (std::size_t i = 0; i < n; ++i) {
    stop_axis.advance(s, sv, -leg_mm + v * kModelStep_s * static_cast<double>(i), v);
    run_axis.advance(r, rv, 0, 0);
  }
  ModelCorner m;
  m.run.reserve(n), m.stop.reserve(n), m.t.reserve(n);
  double furthest = -1e300;
  for (std::size_t i = 0; i < n; ++i) {
    stop_axis.advance(s, sv, 0, 0);
    run_axis.advance(r, rv, v * kModelStep_s * static_cast<double>(i), v);
    if (r <= furthest) continue;  // keep the running axis increasing for the lookup
    furthest = r;
    m.run.push_back(r), m.stop.push_back(s), m.t.push_back(kModelStep_s * static_cast<double>(i));
  }
  return m;
}

// A corner's second leg as measured: places along it (mm past the corner) and the centre across
// it (mm in the picture's frame, turn taken out).
struct MeasuredLeg {
  std::vector<double> run, centre;
};

class LegReader {
 public:
  LegReader(const PlacedPicture& p, const std::string& where) : p_(p), where_(where) {}

  // The picture's frame: mm with y up, placed by the marks' box.
  double col_of(double x) const { return p_.box_x0 + (x - p_.lo.x) / p_.pixel_mm; }
  double row_of(double y) const { return p_.box_y0 + (p_.hi.y - y) / p_.pixel_mm; }
  double x_of(int col) const { return p_.lo.x + (col - p_.box_x0) * p_.pixel_mm; }
  double y_of(int row) const { return p_.hi.y - (row - p_.box_y0) * p_.pixel_mm; }

  // The ink's centroid across a line along `axis` (0: x), at `along` (mm), within `half` of
  // `centre` (mm, across); false when no ink is there.
  bool centroid(int axis, double along, double centre, double half, double& out) const {
    const PatternMarks& m = p_.marks;
    double w = 0, wc = 0;
    if (axis == 1) {  // a line along y: a row, across its columns
      const int row = static_cast<int>(std::lround(row_of(along)));
      if (row < 0 || row >= m.height()) return false;
      const int c0 = std::max(0, static_cast<int>(std::floor(col_of(centre - half))));
      const int c1 = std::min(m.width() - 1, static_cast<int>(std::ceil(col_of(centre + half))));
      for (int c = c0; c <= c1; ++c) {
        const double ink = std::max(0.0, m.ink(c, row));
        w += ink, wc += ink * x_of(c);
      }
    } else {  // a line along x: a column, across its rows
      const int col = static_cast<int>(std::lround(col_of(along)));
      if (col < 0 || col >= m.width()) return false;
      const int r0 = std::max(0, static_cast<int>(std::floor(row_of(centre + half))));
      const int r1 = std::min(m.height() - 1, static_cast<int>(std::ceil(row_of(centre - half))));
      for (int r = r0; r <= r1; ++r) {
        const double ink = std::max(0.0, m.ink(col, r));
        w += ink, wc += ink * y_of(r);
      }
    }
    if (!(w > 0)) return false;
    out = wc / w;
    return true;
  }

  // The corner's second leg, measured row by row (or column by column).
  MeasuredLeg read(const LagCorner& c, double leg, double run_tau_s) const {
    const int a = c.axis, r = 1 - a;  // the stopping and the running axis
    auto along_of = [](Vec2 p, int axis) { return axis == 0 ? p.x : p.y; };
    const double turn_leg1 = a == 0 ? p_.turn_x : p_.turn_y;  // d(run)/d(stop) of a first leg
    const double turn_leg2 = a == 0 ? p_.turn_y : p_.turn_x;  // d(stop)/d(run) of a second leg
    const double corner_stop = along_of(c.corner, a), corner_run = along_of(c.corner, r);
    // 1. The first leg's centre across it at its middle, carried to the corner along its tilt.
    double leg1 = 0;
    if (!centroid(a, corner_stop - leg / 2, corner_run, kFindWindow_mm, leg1)) fail(c, "first leg");
    const double run0 = leg1 + turn_leg1 * leg / 2;
    // The second leg's settled centre, 60 % along it.
    const double mid_run = run0 + 0.6 * leg;
    double mid = 0;
    if (!centroid(r, mid_run, corner_stop, kFindWindow_mm, mid)) fail(c, "second leg");
    // 2. Row by row along the second leg.
    MeasuredLeg out;
    const double last = leg - c.speed_mm_s * run_tau_s - kBeforeEnd_mm;
    for (double d = kFromCorner_mm; d <= last; d += p_.pixel_mm) {
      const double run = run0 + d;
      const double expect = mid + turn_leg2 * (run - mid_run);
      double centre = 0;
      if (!centroid(r, run, expect, kLegWindow_mm, centre)) continue;
      out.run.push_back(d);
      out.centre.push_back(centre - turn_leg2 * (run - mid_run));
    }
    if (out.run.size() < 10) fail(c, "second leg (fewer than 10 places measured along it)");
    return out;
  }

 private:
  [[noreturn]] void fail(const LagCorner& c, const std::string& what) const {
    throw InputError("'" + where_ + "': the " + (c.axis == 0 ? "x" : "y") + " corner at " + pattern_figure(c.speed_mm_s) +
                     " mm/s has no mark where its " + what +
                     " should be: not a picture of this pattern, or turned by more than 1.5°");
  }
  const PlacedPicture& p_;
  const std::string& where_;
};

// Residuals of one model on one measured leg, with the leg's offset (its settled place in the
// picture) taken out: the sum of squares, and the offset.
double squared_residuals(const MeasuredLeg& m, const ModelCorner& model, double& offset) {
  const std::size_t n = m.run.size();
  std::vector<double> diff(n);
  double mean = 0;
  for (std::size_t k = 0; k < n; ++k) mean += diff[k] = m.centre[k] - model.stop_at(m.run[k]);
  mean /= static_cast<double>(n);
  double sum = 0;
  for (double d : diff) sum += (d - mean) * (d - mean);
  offset = mean;
  return sum;
}

}  // namespace

CornerFit fit_corners(const PlacedPicture& picture, const LagPattern& pattern, double tau_x_s, double tau_y_s,
                      const std::string& where) {
  CornerFit fit;
  if (pattern.corners.empty()) return fit;
  const LegReader reader(picture, where);
  const double tau[2] = {tau_x_s, tau_y_s};
  std::vector<MeasuredLeg> legs;
  std::size_t places = 0;
  for (const LagCorner& c : pattern.corners) {
    legs.push_back(reader.read(c, pattern.corner_leg_mm, tau[1 - c.axis]));
    places += legs.back().run.size();
  }
  // Every corner under one model (zeta 0: first order); per-corner sums and offsets kept.
  auto evaluate = [&](double zeta, std::vector<double>* sums, std::vector<double>* offsets) {
    const AxisServo axes[2] = {AxisServo(tau_x_s, zeta), AxisServo(tau_y_s, zeta)};
    double total = 0;
    for (std::size_t i = 0; i < legs.size(); ++i) {
      const LagCorner& c = pattern.corners[i];
      const ModelCorner m = model_corner(pattern.corner_leg_mm, c.speed_mm_s, axes[c.axis], axes[1 - c.axis]);
      double offset = 0;
      const double s = squared_residuals(legs[i], m, offset);
      total += s;
      if (sums) sums->push_back(s);
      if (offsets) offsets->push_back(offset);
    }
    return total;
  };
  // ζ: a log scan, then golden-section refinement in log ζ between the best scan point's neighbours.
  constexpr int kScan = 41;
  const double lo = std::log(0.1), hi = std::log(10.0), h = (hi - lo) / (kScan - 1);
  int best = 0;
  double best_cost = 1e300;
  for (int i = 0; i < kScan; ++i) {
    const double cost = evaluate(std::exp(lo + h * i), nullptr, nullptr);
    if (cost < best_cost) best_cost = cost, best = i;
  }
  double a = lo + h * std::max(0, best - 1), b = lo + h * std::min(kScan - 1, best + 1);
  const double g = (std::sqrt(5.0) - 1) / 2;
  double u = b - g * (b - a), w = a + g * (b - a);
  double fu = evaluate(std::exp(u), nullptr, nullptr), fw = evaluate(std::exp(w), nullptr, nullptr);
  for (int i = 0; i < 30; ++i) {
    if (fu < fw) b = w, w = u, fw = fu, u = b - g * (b - a), fu = evaluate(std::exp(u), nullptr, nullptr);
    else a = u, u = w, fu = fw, w = a + g * (b - a), fw = evaluate(std::exp(w), nullptr, nullptr);
  }
  fit.zeta = std::exp((a + b) / 2);
  fit.omega_n_rad_s = 2 * fit.zeta / ((tau_x_s + tau_y_s) / 2);

  std::vector<double> first_sums, second_sums, first_offsets, second_offsets;
  const double first = evaluate(0, &first_sums, &first_offsets);
  const double second = evaluate(fit.zeta, &second_sums, &second_offsets);
  const double n = static_cast<double>(places);
  fit.rms_first_um = std::sqrt(first / n) * 1e3;
  fit.rms_second_um = std::sqrt(second / n) * 1e3;
  fit.second_order = fit.rms_second_um < 0.5 * fit.rms_first_um && fit.zeta < 3;
  const std::vector<double>& offsets = fit.second_order ? second_offsets : first_offsets;
  // What the chosen servo model leaves, in the time since each corner: a mirror resonance rings
  // there (ring_fit.hpp).
  {
    const double zeta = fit.second_order ? fit.zeta : 0;
    const AxisServo axes[2] = {AxisServo(tau_x_s, zeta), AxisServo(tau_y_s, zeta)};
    std::vector<RingTrace> traces;
    for (std::size_t i = 0; i < legs.size(); ++i) {
      const LagCorner& c = pattern.corners[i];
      const ModelCorner m = model_corner(pattern.corner_leg_mm, c.speed_mm_s, axes[c.axis], axes[1 - c.axis]);
      RingTrace trace;
      for (std::size_t k = 0; k < legs[i].run.size(); ++k) {
        trace.t_s.push_back(m.time_at(legs[i].run[k]));
        trace.residual_mm.push_back(legs[i].centre[k] - m.stop_at(legs[i].run[k]) - offsets[i]);
      }
      traces.push_back(std::move(trace));
    }
    fit.ring = fit_ring(traces);
  }
  for (std::size_t i = 0; i < legs.size(); ++i) {
    CornerFigure f;
    f.axis = pattern.corners[i].axis;
    f.speed_mm_s = pattern.corners[i].speed_mm_s;
    const MeasuredLeg& m = legs[i];
    f.rows = static_cast<int>(m.run.size());
    double most = -1e300;
    for (double c : m.centre) most = std::max(most, c - offsets[i]);
    f.overshoot_um = std::max(0.0, most) * 1e3;
    f.rms_first_um = std::sqrt(first_sums[i] / static_cast<double>(f.rows)) * 1e3;
    f.rms_second_um = std::sqrt(second_sums[i] / static_cast<double>(f.rows)) * 1e3;
    fit.corners.push_back(f);
  }
  return fit;
}

}  // namespace mark

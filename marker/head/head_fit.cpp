#include "marker/head/head_fit.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

#include "base/error.hpp"

namespace mark {
namespace {

// The second-order fit is chosen only when it explains the record clearly better and is a
// second-order response at all: with ζ ≥ 3 its two poles are ≥ 4ζ² = 36× apart, the fast one
// inside a tick — a first-order head with a sub-tick delay (a sampled servo, or the
// simulator's integration step), which the first-order model with the same lag plans as well.
constexpr double kSecondOrderGain = 0.5;
constexpr double kMaxSecondOrderZeta = 3.0;
// The speed of a large step counts as its acceleration phase between these shares of the peak.
constexpr double kRiseLo = 0.15, kRiseHi = 0.85;

double axis_of(const ScanSample& s, int axis) { return axis == 0 ? s.x_mm : s.y_mm; }
double axis_of(const Vec2& p, int axis) { return axis == 0 ? p.x : p.y; }

// A linear servo's response over one tick with the command moving linearly from c0 to c1:
// state (x, v) ← Φ·(x, v) + g0·c0 + g1·c1 (v unused by the first order).
struct TickMap {
  std::array<double, 4> phi{};  // row-major 2×2
  std::array<double, 2> g0{}, g1{};
};

TickMap first_order_map(double tau, double tick) {
  // x(T) = c1 − rτ + (x0 − c0 + rτ)·e^(−T/τ), r = (c1 − c0)/T: exact for a linear command.
  const double e = std::exp(-tick / tau), q = tau / tick;
  TickMap m;
  m.phi = {e, 0, 0, 0};
  m.g0 = {q - e * (1 + q), 0};
  m.g1 = {1 - q + e * q, 0};
  return m;
}

TickMap second_order_map(double wn, double zeta, double tick) {
  // ẍ = ωn²(c − x) − 2ζωn·ẋ is linear: integrate the unit responses once (RK4, fine steps) and
  // superpose them per tick.
  auto response = [&](double x, double v, double c0, double c1) {
    const int n = 32;
    const double h = tick / n;
    auto f = [&](double t, double xx, double vv, double& dx, double& dv) {
      const double c = c0 + (c1 - c0) * t / tick;
      dx = vv;
      dv = wn * wn * (c - xx) - 2 * zeta * wn * vv;
    };
    for (int i = 0; i < n; ++i) {
      const double t = i * h;
      double k1x, k1v, k2x, k2v, k3x, k3v, k4x, k4v;
      f(t, x, v, k1x, k1v);
      f(t + h / 2, x + h / 2 * k1x, v + h / 2 * k1v, k2x, k2v);
      f(t + h / 2, x + h / 2 * k2x, v + h / 2 * k2v, k3x, k3v);
      f(t + h, x + h * k3x, v + h * k3v, k4x, k4v);
      x += h / 6 * (k1x + 2 * k2x + 2 * k3x + k4x);
      v += h / 6 * (k1v + 2 * k2v + 2 * k3v + k4v);
    }
    return std::array<double, 2>{x, v};
  };
  const auto ex = response(1, 0, 0, 0), ev = response(0, 1, 0, 0);
  const auto e0 = response(0, 0, 1, 0), e1 = response(0, 0, 0, 1);
  TickMap m;
  m.phi = {ex[0], ev[0], ex[1], ev[1]};
  m.g0 = {e0[0], e0[1]};
  m.g1 = {e1[0], e1[1]};
  return m;
}

struct LinearPart {
  std::size_t first, count;
  int axis;
};

// Sum of squared position errors of the model over the linear parts; each part starts from the
// recorded position before it, at rest (the pattern holds before every part).
double sse(const ResponseRecord& r, const std::vector<LinearPart>& parts, const TickMap& m,
           std::size_t* points = nullptr) {
  double sum = 0;
  std::size_t n = 0;
  for (const LinearPart& part : parts) {
    double x = axis_of(r.position[part.first - 1], part.axis), v = 0;
    double c0 = axis_of(r.pattern.commands[part.first - 1], part.axis);
    for (std::size_t k = part.first; k < part.first + part.count; ++k) {
      const double c1 = axis_of(r.pattern.commands[k], part.axis);
      const double nx = m.phi[0] * x + m.phi[1] * v + m.g0[0] * c0 + m.g1[0] * c1;
      const double nv = m.phi[2] * x + m.phi[3] * v + m.g0[1] * c0 + m.g1[1] * c1;
      x = nx, v = nv, c0 = c1;
      const double e = x - axis_of(r.position[k], part.axis);
      sum += e * e;
      ++n;
    }
  }
  if (points) *points = n;
  return sum;
}

// Minimum of a unimodal-near-the-minimum function of one variable: a log-spaced scan, then
// golden-section search between the best point's neighbours.
template <class F>
double minimize_log(F f, double lo, double hi, int scan = 80) {
  double best_u = std::log(lo), best = f(lo);
  const double step = (std::log(hi) - std::log(lo)) / scan;
  for (int i = 1; i <= scan; ++i) {
    const double u = std::log(lo) + i * step, val = f(std::exp(u));
    if (val < best) best = val, best_u = u;
  }
  double a = best_u - step, b = best_u + step;
  const double g = (std::sqrt(5.0) - 1) / 2;
  double c = b - g * (b - a), d = a + g * (b - a);
  double fc = f(std::exp(c)), fd = f(std::exp(d));
  for (int i = 0; i < 80 && b - a > 1e-10; ++i) {
    if (fc < fd) {
      b = d, d = c, fd = fc, c = b - g * (b - a), fc = f(std::exp(c));
    } else {
      a = c, c = d, fc = fd, d = a + g * (b - a), fd = f(std::exp(d));
    }
  }
  return std::exp((a + b) / 2);
}

// Nelder–Mead over two variables.
template <class F>
std::array<double, 2> nelder_mead(F f, std::array<double, 2> start, double step) {
  std::array<std::array<double, 2>, 3> p = {start, start, start};
  p[1][0] += step;
  p[2][1] += step;
  std::array<double, 3> v = {f(p[0]), f(p[1]), f(p[2])};
  for (int it = 0; it < 400; ++it) {
    std::array<int, 3> o = {0, 1, 2};
    std::sort(o.begin(), o.end(), [&](int a, int b) { return v[a] < v[b]; });
    const auto best = p[o[0]], mid = p[o[1]], worst = p[o[2]];
    if (std::abs(v[o[2]] - v[o[0]]) <= 1e-14 * (std::abs(v[o[0]]) + 1e-300) &&
        std::abs(worst[0] - best[0]) + std::abs(worst[1] - best[1]) < 1e-9)
      break;
    const std::array<double, 2> cen = {(best[0] + mid[0]) / 2, (best[1] + mid[1]) / 2};
    auto along = [&](double t) {
      return std::array<double, 2>{cen[0] + t * (worst[0] - cen[0]), cen[1] + t * (worst[1] - cen[1])};
    };
    const auto refl = along(-1);
    const double fr = f(refl);
    if (fr < v[o[0]]) {
      const auto exp = along(-2);
      const double fe = f(exp);
      if (fe < fr) p[o[2]] = exp, v[o[2]] = fe;
      else p[o[2]] = refl, v[o[2]] = fr;
    } else if (fr < v[o[1]]) {
      p[o[2]] = refl, v[o[2]] = fr;
    } else {
      const auto con = along(0.5);
      const double fc = f(con);
      if (fc < v[o[2]]) {
        p[o[2]] = con, v[o[2]] = fc;
      } else {  // shrink towards the best
        for (int k : {o[1], o[2]}) {
          p[k] = {(p[k][0] + best[0]) / 2, (p[k][1] + best[1]) / 2};
          v[k] = f(p[k]);
        }
      }
    }
  }
  return p[static_cast<std::size_t>(std::min_element(v.begin(), v.end()) - v.begin())];
}

// Central-difference speed of one axis at every interior sample of [first, first + count).
std::vector<double> speeds(const ResponseRecord& r, std::size_t first, std::size_t count, int axis) {
  std::vector<double> v(count, 0.0);
  const double tick = r.pattern.tick_s;
  for (std::size_t i = 1; i + 1 < count; ++i)
    v[i] = (axis_of(r.position[first + i + 1], axis) - axis_of(r.position[first + i - 1], axis)) /
           (2 * tick);
  return v;
}

// Slope of |v| against time over the rise of one movement: least squares over the samples
// between kRiseLo and kRiseHi of its peak, before the peak. 0 if there are too few.
double rise_slope(const std::vector<double>& v, std::size_t from, std::size_t to, double tick) {
  std::size_t peak_at = from;
  for (std::size_t i = from; i < to; ++i)
    if (std::abs(v[i]) > std::abs(v[peak_at])) peak_at = i;
  const double peak = std::abs(v[peak_at]);
  double st = 0, sv = 0, stt = 0, stv = 0;
  int n = 0;
  for (std::size_t i = from; i < peak_at; ++i) {
    const double s = std::abs(v[i]);
    if (s < kRiseLo * peak || s > kRiseHi * peak) continue;
    const double t = static_cast<double>(i) * tick;
    st += t, sv += s, stt += t * t, stv += t * s;
    ++n;
  }
  if (n < 4) return 0;
  return (n * stv - st * sv) / (n * stt - st * st);
}

}  // namespace

HeadProfile fit_head_profile(const ResponseRecord& r, const std::string& head_name, double field_mm) {
  if (r.position.size() != r.pattern.commands.size())
    throw InputError("head response of " + head_name + ": the record and the pattern differ in length");
  const double tick = r.pattern.tick_s;
  std::vector<LinearPart> linear;
  for (const ResponsePart& p : r.pattern.parts)
    if (p.kind != ResponsePartKind::large_step && p.first > 0 && p.count > 0 &&
        p.first + p.count <= r.position.size())
      linear.push_back({p.first, p.count, p.axis});
  if (linear.empty()) throw InputError("head response of " + head_name + ": no linear test parts");

  HeadProfile out;
  out.head = head_name;
  out.field_mm = field_mm;
  out.tick_s = tick;

  // First order: τ.
  out.tau_s = minimize_log([&](double tau) { return sse(r, linear, first_order_map(tau, tick)); },
                           1e-6, 1e-2);
  std::size_t points = 0;
  const double sse1 = sse(r, linear, first_order_map(out.tau_s, tick), &points);
  // Second order: (ωn, ζ) from the best of a few dampings with the first order's ramp lag.
  auto cost2 = [&](const std::array<double, 2>& u) {
    return sse(r, linear, second_order_map(std::exp(u[0]), std::exp(u[1]), tick));
  };
  std::array<double, 2> start{};
  double best = INFINITY;
  for (double zeta : {0.3, 0.5, 0.7, 1.0, 1.5, 2.5, 4.0}) {
    const std::array<double, 2> u = {std::log(2 * zeta / out.tau_s), std::log(zeta)};
    const double c = cost2(u);
    if (c < best) best = c, start = u;
  }
  const auto u = nelder_mead(cost2, start, 0.2);
  out.omega_n_rad_s = std::exp(u[0]);
  out.zeta = std::exp(u[1]);
  const double sse2 = cost2(u);
  const double n = static_cast<double>(std::max<std::size_t>(points, 1));
  out.fit_rms_first_um = std::sqrt(sse1 / n) * 1e3;
  out.fit_rms_second_um = std::sqrt(sse2 / n) * 1e3;
  out.model = out.zeta < kMaxSecondOrderZeta && sse2 < kSecondOrderGain * kSecondOrderGain * sse1
                  ? ServoOrder::second
                  : ServoOrder::first;

  // Limits from the large steps: the top speed of any, the acceleration of the largest.
  double top = 0, largest = 0;
  for (const ResponsePart& p : r.pattern.parts)
    if (p.kind == ResponsePartKind::large_step) largest = std::max(largest, p.size_mm);
  std::vector<double> accels;
  for (const ResponsePart& p : r.pattern.parts) {
    if (p.kind != ResponsePartKind::large_step || p.first + p.count > r.position.size()) continue;
    const std::vector<double> v = speeds(r, p.first, p.count, p.axis);
    for (double s : v) top = std::max(top, std::abs(s));
    if (p.size_mm < largest) continue;
    // Two movements: there, and back from the middle of the part on.
    const std::size_t half = p.count / 2;
    for (auto [from, to] : {std::pair<std::size_t, std::size_t>{0, half}, {half, p.count}}) {
      const double a = rise_slope(v, from, to, tick);
      if (a > 0) accels.push_back(a);
    }
  }
  if (!(top > 0) || accels.empty())
    throw InputError("head response of " + head_name + ": the large steps show no motion");
  std::sort(accels.begin(), accels.end());
  out.max_speed_mm_s = top;
  out.max_accel_mm_s2 = accels[accels.size() / 2];
  out.source = "identified";
  return out;
}

HeadProfile identify_head(const SimScannerOptions& head) {
  const ResponsePattern pattern = head_response_pattern(head.head.field_mm, head.tick_s);
  return fit_head_profile(measure_head_response(head, pattern), head.head.name, head.head.field_mm);
}

}  // namespace mark

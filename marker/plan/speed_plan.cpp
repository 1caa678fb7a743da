#include "marker/plan/speed_plan.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include "marker/plan/plan.hpp"

namespace mark {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
// Moves shorter than this take no time and do not separate two others (the locus skips them).

// ρ(θ) = (rx² sin²θ + ry² cos²θ)^(3/2) / (rx·ry) along an ellipse, smallest at the ends of its
// longer axis; over an arc of it, at those points if the sweep includes them, else at an end.
double ellipse_min_radius(const EllipticalArc& e) {
  auto rho = [&](double th) {
    const double sn = std::sin(th), c = std::cos(th);
    const double g2 = e.rx * e.rx * sn * sn + e.ry * e.ry * c * c;
    return g2 * std::sqrt(g2) / (e.rx * e.ry);
  };
  const double a = std::min(e.start_param, e.start_param + e.sweep);
  const double b = std::max(e.start_param, e.start_param + e.sweep);
  double best = std::min(rho(a), rho(b));
  // Candidates: θ = kπ (vertices on the x axis) when rx > ry, θ = π/2 + kπ otherwise.
  const double offset = e.rx > e.ry ? 0.0 : std::numbers::pi / 2;
  for (double th = std::ceil((a - offset) / std::numbers::pi) * std::numbers::pi + offset; th <= b;
       th += std::numbers::pi)
    best = std::min(best, rho(th));
  return best;
}

bool is_move(const Command& c) { return c.kind != CommandKind::dwell && c.length >= kMinLength_mm; }

}  // namespace

double min_radius_mm(const Element& e) {
  switch (e.kind()) {
    case ElementKind::line: return kInf;
    case ElementKind::arc: return std::get<CircularArc>(e.geometry()).radius;
    case ElementKind::ellipse: return ellipse_min_radius(std::get<EllipticalArc>(e.geometry()));
  }
  return kInf;
}

void plan_speeds(std::vector<Command>& commands, const Pen& pen) {
  const std::size_t n = commands.size();
  // v[i]: speed at the start of command i; v[n] at the end of the job. Dwells pin both of their
  // ends to zero; moves too short to count pass the speed through.
  std::vector<double> vmax(n, 0.0), accel(n, 0.0), decel(n, 0.0);
  std::vector<double> v(vmax.size(), kInf);
  v.push_back(kInf);
  // On a curve the centripetal acceleration takes part of the head's limit: the tangential rate
  // is what is left of it. The centripetal share is capped at √0.99 of the limit, so at least a
  // tenth of the limit is always left for speeding up and slowing down.
  const double limit = pen.accel_limit_mm_s2;
  double full_power = 0;
  std::vector<bool> curved(n, false);
  for (std::size_t i = 0; i < n; ++i) {
    Command& c = commands[i];
    if (!is_move(c)) continue;
    const double r = min_radius_mm(c.path);
    curved[i] = !std::isinf(r);
    double centripetal = pen.curve_accel_mm_s2;
    if (curved[i] && limit > 0) centripetal = std::min(centripetal, std::sqrt(0.99) * limit);
    vmax[i] = std::min(c.speed_mm_s, curved[i] ? std::sqrt(centripetal * r) : kInf);
    if (c.laser()) full_power = std::max(full_power, vmax[i]);
  }
  auto tangential = [&](std::size_t i, double rate) {
    if (!curved[i] || !(limit > 0)) return rate;
    const double r = min_radius_mm(commands[i].path);
    const double ac = vmax[i] * vmax[i] / r;
    return std::min(rate, std::sqrt(std::max(limit * limit - ac * ac, 0.01 * limit * limit)));
  };
  for (std::size_t i = 0; i < n; ++i) {
    if (!is_move(commands[i])) continue;
    if (commands[i].laser()) {
      accel[i] = decel[i] = tangential(i, pen.accel_mm_s2);
      continue;
    }
    accel[i] = tangential(i, pen.jump_accel_mm_s2);
    // A laser-off move arrives at the next move's start: gently if that one is lit.
    std::size_t next = i + 1;
    while (next < n && commands[next].kind != CommandKind::dwell && !is_move(commands[next])) ++next;
    decel[i] = tangential(i, next < n && is_move(commands[next]) && commands[next].laser()
                                 ? pen.accel_mm_s2
                                 : pen.jump_accel_mm_s2);
  }
  // Junction limits.
  v[0] = 0;
  v[n] = 0;
  std::size_t prev = n;  // the last move since the job's start or the last dwell (n: none)
  std::size_t since = 0;  // first command after that move or dwell
  for (std::size_t i = 0; i < n; ++i) {
    const Command& c = commands[i];
    if (c.kind == CommandKind::dwell) {
      v[i] = v[i + 1] = 0;
      prev = n;
      since = i + 1;
      continue;
    }
    if (!is_move(c)) continue;
    if (prev == n) {
      v[i] = 0;  // from rest: the job's start or a dwell
    } else {
      const double s = std::sin(turn_angle_rad(commands[prev].path, c.path) / 2);
      // The velocity step happens within one tick: together with the rates on either side it
      // must stay within the head's limit.
      double dv = pen.junction_dv_mm_s;
      if (limit > 0)
        dv = std::min(dv, std::max(0.0, limit - std::max({accel[prev], decel[prev], accel[i], decel[i]})) *
                              pen.tick_s);
      const double turn_limit = s > 1e-12 ? dv / (2 * s) : kInf;
      v[i] = std::min({v[i], vmax[prev], vmax[i], turn_limit});
      // The laser switches on the tick, so at speed v its edge lands anywhere within v·tick of
      // the point: at rest, unless the pen allows a speed (blanking's straight run-ins and
      // run-outs are there to switch at speed) and the path runs straight on.
      if (commands[prev].laser() != c.laser())
        v[i] = s > 1e-9 ? 0.0 : std::min(v[i], pen.laser_switch_speed_mm_s);
    }
    for (std::size_t k = since; k < i; ++k) v[k] = std::min(v[k], v[i]);  // too short to count
    prev = i;
    since = i + 1;
  }
  // Every junction at most the speeds of both moves it joins.
  for (std::size_t i = 0; i < n; ++i)
    if (is_move(commands[i])) {
      v[i] = std::min(v[i], vmax[i]);
      v[i + 1] = std::min(v[i + 1], vmax[i]);
    }

  // Backward pass: slow enough to stop (or reach the next junction speed) in time.
  for (std::size_t i = n; i-- > 0;) {
    if (!is_move(commands[i])) {
      if (commands[i].kind != CommandKind::dwell) v[i] = std::min(v[i], v[i + 1]);
      continue;
    }
    v[i] = std::min(v[i], std::sqrt(v[i + 1] * v[i + 1] + 2 * decel[i] * commands[i].length));
  }
  // Forward pass: no faster than reachable from the previous junction.
  for (std::size_t i = 0; i < n; ++i) {
    if (!is_move(commands[i])) {
      if (commands[i].kind != CommandKind::dwell) v[i + 1] = std::min(v[i + 1], v[i]);
      continue;
    }
    v[i + 1] = std::min(v[i + 1], std::sqrt(v[i] * v[i] + 2 * accel[i] * commands[i].length));
  }

  for (std::size_t i = 0; i < n; ++i) {
    Command& c = commands[i];
    if (c.kind == CommandKind::dwell) continue;
    c.accel_mm_s2 = is_move(c) ? accel[i] : pen.jump_accel_mm_s2;
    c.decel_mm_s2 = is_move(c) ? decel[i] : pen.jump_accel_mm_s2;
    c.speed_mm_s = is_move(c) ? vmax[i] : c.speed_mm_s;
    c.entry_speed_mm_s = v[i];
    c.exit_speed_mm_s = v[i + 1];
    c.full_power_speed_mm_s = c.laser() ? full_power : 0;
    c.min_lit_speed_mm_s = c.laser() ? pen.min_lit_speed_mm_s : 0;
  }
}

}  // namespace mark

#include "marker/locus/planned_locus.hpp"

#include <algorithm>
#include <cmath>
#include <type_traits>
#include <variant>

namespace mark {
namespace {

constexpr double kMinLength_mm = 1e-9;  // as the constant-speed generator: shorter is a point
constexpr double kTimeEps = 1e-12;      // s: a sample exactly on a command's end belongs to it

SpeedProfile profile_of(const Command& c) {
  if (c.planned())
    return SpeedProfile::make(c.length, c.entry_speed_mm_s, c.exit_speed_mm_s, c.speed_mm_s,
                              c.accel_mm_s2, c.decel_mm_s2);
  // An unplanned move inside a planned job runs at constant speed.
  return SpeedProfile::make(c.length, c.speed_mm_s, c.speed_mm_s, c.speed_mm_s, 1, 1);
}

// Curvature vector d²P/ds² of an element at parameter t ∈ {0, 1} (its start or end).
Point curvature_at(const Element& e, double t) {
  return std::visit(
      [&](const auto& g) -> Point {
        using G = std::decay_t<decltype(g)>;
        if constexpr (std::is_same_v<G, Line>) {
          return Point(0, 0);
        } else if constexpr (std::is_same_v<G, CircularArc>) {
          const double th = g.start_angle + t * g.sweep;
          return -Point(std::cos(th), std::sin(th)) / g.radius;
        } else {
          const double th = g.start_param + t * g.sweep;
          const double c = std::cos(th), sn = std::sin(th), rc = std::cos(g.rotation),
                       rs = std::sin(g.rotation);
          const Point d1(-g.rx * sn, g.ry * c), d2(-g.rx * c, -g.ry * sn);
          const double g2 = d1.squaredNorm();
          const Point k = (d2 - (d2.dot(d1) / g2) * d1) / g2;  // the sweep's sign cancels
          return Point(rc * k.x() - rs * k.y(), rs * k.x() + rc * k.y());
        }
      },
      e.geometry());
}

// The path's acceleration vector at the start (t = 0) or end (t = 1) of a planned move.
Point accel_at(const Command& c, const SpeedProfile& p, double t) {
  if (c.kind == CommandKind::dwell) return Point(0, 0);
  const double tangential = t == 0 ? (p.t1 > 0 ? p.a : (p.t2 < p.duration && p.t2 <= 0 ? -p.d : 0.0))
                                   : (p.duration > p.t2 ? -p.d : (p.t1 >= p.duration ? p.a : 0.0));
  const double v = t == 0 ? p.v0 : p.v1;
  return tangential * c.path.tangent_at(t) + (v * v) * curvature_at(c.path, t);
}

double duration_of(const Command& c, double tick_s) {
  if (c.kind == CommandKind::dwell) return c.dwell_ticks * tick_s;
  if (c.length < kMinLength_mm) return 0;
  return profile_of(c).duration;
}

}  // namespace

double PlannedLocus::duration_s(std::span<const Command> commands, double tick_s) {
  double t = 0;
  for (const Command& c : commands) t += duration_of(c, tick_s);
  return t;
}

std::uint64_t PlannedLocus::count_samples(std::span<const Command> commands, double tick_s) {
  const double ticks = duration_s(commands, tick_s) / tick_s;
  return ticks > 0 ? static_cast<std::uint64_t>(std::ceil(ticks - 1e-9)) : 0;
}

PlannedLocus::PlannedLocus(std::span<const Command> commands, double tick_s, FeedForward ff)
    : commands_(commands), tick_s_(tick_s), ff_(ff), total_(count_samples(commands, tick_s)) {
  for (std::size_t i = 0; i < commands.size(); ++i)
    if (duration_of(commands[i], tick_s) > 0) last_timed_ = i;
}

bool PlannedLocus::advance() {
  // The acceleration the current command ends with: the next samples' tick means reach back
  // into it.
  prev_end_accel_ = current_ && current_->kind != CommandKind::dwell
                        ? accel_at(*current_, profile_, 1)
                        : Point(0, 0);
  while (next_ < commands_.size()) {
    const Command& c = commands_[next_++];
    const double d = duration_of(c, tick_s_);
    if (!(d > 0)) continue;
    current_ = &c;
    // ... and the one the next command starts with.
    next_start_accel_ = Point(0, 0);
    for (std::size_t j = next_; j < commands_.size(); ++j) {
      const Command& n = commands_[j];
      if (!(duration_of(n, tick_s_) > 0)) continue;
      if (n.kind != CommandKind::dwell) next_start_accel_ = accel_at(n, profile_of(n), 0);
      break;
    }
    t0_ = t_end_;
    t_end_ = t0_ + d;
    path0_ += loaded_length_;
    loaded_length_ = c.kind == CommandKind::dwell ? 0.0 : c.length;
    // Samples with (k + 1)·tick ≤ t_end (−1: none yet); the last command takes the rest.
    k_last_ = next_ == last_timed_ + 1 ? static_cast<std::int64_t>(total_) - 1
                             : static_cast<std::int64_t>(std::floor(t_end_ / tick_s_ - 1 + 1e-9));
    kind_ = c.kind;
    laser_ = c.laser();
    power_per_speed_ =
        c.laser() && c.full_power_speed_mm_s > 0 ? 255.0 / c.full_power_speed_mm_s : 0.0;
    min_lit_speed_ = c.min_lit_speed_mm_s;
    if (c.kind == CommandKind::dwell) {
      p0_ = c.start();
      return true;
    }
    profile_ = profile_of(c);
    std::visit(
        [&](const auto& g) {
          using G = std::decay_t<decltype(g)>;
          if constexpr (std::is_same_v<G, Line>) {
            p0_ = g.start;
            u_ = (g.end - g.start) / c.length;
          } else if constexpr (std::is_same_v<G, CircularArc>) {
            center_ = g.center;
            radius_ = g.radius;
            angle0_ = g.start_angle;
            turn_ = g.sweep >= 0 ? 1.0 : -1.0;
          } else {
            table_.build(c.path);
            cursor_ = 0;
          }
        },
        c.path.geometry());
    return true;
  }
  return false;
}

inline void PlannedLocus::emit(ScanSample& o, double tau) {
  Point p, vel, acc;
  if (kind_ == CommandKind::dwell) {
    p = p0_;
    vel = acc = Point(0, 0);
    o.power = 255;  // a lit dwell is a deliberate lit wait
    o.laser = laser_;
  } else {
    const SpeedProfile& pr = profile_;
    tau = std::clamp(tau, 0.0, pr.duration);
    const double s = pr.position(tau), v = pr.speed(tau), a = pr.accel(tau);
    Point t, k;
    switch (kind_) {
      case CommandKind::arc: {
        const double th = angle0_ + turn_ * s / radius_;
        const double c = std::cos(th), sn = std::sin(th);
        p = center_ + radius_ * Point(c, sn);
        t = turn_ * Point(-sn, c);
        k = Point(-c, -sn) / radius_;
        break;
      }
      case CommandKind::ellipse:
        table_.frame_at(s, cursor_, p, t, k);
        break;
      default:  // jump, line
        p = p0_ + s * u_;
        t = u_;
        k = Point(0, 0);
        break;
    }
    vel = v * t;
    // The second-order term needs the acceleration, which jumps where the profile changes
    // phase: the head sees the command held linearly between samples, so each sample carries
    // the mean tangential acceleration over its own tick (±half a tick around it) — a step in
    // the command then ramps across the samples with the step's area, centred on it.
    if (ff_.inertia_s2 > 0) {
      const double half = 0.5 * tick_s_;
      const double lo = std::max(0.0, tau - half), hi = std::min(pr.duration, tau + half);
      acc = ((pr.speed(hi) - pr.speed(lo)) * t + (hi - lo) * (v * v) * k +
             std::max(0.0, half - tau) * prev_end_accel_ +
             std::max(0.0, tau + half - pr.duration) * next_start_accel_) /
            tick_s_;
    } else {
      acc = a * t + (v * v) * k;
    }
    // Power ∝ the path length this tick covers (the sample's laser state holds for the tick
    // ending at it): constant pulse spacing, so the dose per mm is the same at every speed.
    const double path = path0_ + s;
    const double tick_speed = (path - last_path_) / tick_s_;
    if (power_per_speed_ > 0)
      o.power = static_cast<std::uint8_t>(
          std::clamp(std::lround(tick_speed * power_per_speed_), 1L, 255L));
    else
      o.power = 255;
    last_path_ = path;
    o.laser = laser_ && tick_speed >= min_lit_speed_;
  }
  const Point x = p + ff_.lag_s * vel + ff_.inertia_s2 * acc;
  o.x_mm = static_cast<float>(x.x());
  o.y_mm = static_cast<float>(x.y());
}

std::size_t PlannedLocus::generate(ScanSample* out, std::size_t capacity) {
  std::size_t written = 0;
  while (written < capacity && k_ < total_) {
    if (static_cast<std::int64_t>(k_) > k_last_) {
      if (!advance()) break;  // cannot happen: total_ counts the same commands
      continue;
    }
    const std::uint64_t n = std::min<std::uint64_t>(
        capacity - written, static_cast<std::uint64_t>(k_last_ - static_cast<std::int64_t>(k_) + 1));
    for (std::uint64_t i = 0; i < n; ++i, ++k_)
      emit(out[written + i], static_cast<double>(k_ + 1) * tick_s_ - t0_);
    written += static_cast<std::size_t>(n);
  }
  return written;
}

}  // namespace mark

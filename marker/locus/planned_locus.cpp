#include "marker/locus/planned_locus.hpp"

#include <algorithm>
#include <cmath>
#include <type_traits>
#include <variant>

namespace mark {
namespace {

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
    : commands_(commands), tick_s_(tick_s), inv_tick_(1 / tick_s), ff_(ff) {
  durations_.reserve(commands.size());
  double total = 0;
  for (std::size_t i = 0; i < commands.size(); ++i) {
    durations_.push_back(duration_of(commands[i], tick_s));
    total += durations_.back();
    if (durations_.back() > 0) last_timed_ = i;
  }
  const double ticks = total / tick_s;
  total_ = ticks > 0 ? static_cast<std::uint64_t>(std::ceil(ticks - 1e-9)) : 0;
}

const EllipseTable& PlannedLocus::ellipse_table(const EllipticalArc& g) {
  // Tables by shape, built around the origin and kept by the producer thread across jobs: a
  // text repeats its letters' ellipses, which differ only in where they are, and a production
  // line marks the same layout part after part. The newest kMaxTables shapes are kept; a table
  // in use stays alive through the shared pointer this generator holds.
  thread_local std::vector<std::pair<EllipticalArc, std::shared_ptr<const EllipseTable>>> cache;
  for (auto it = cache.begin(); it != cache.end(); ++it) {
    const EllipticalArc& key = it->first;
    if (key.rx == g.rx && key.ry == g.ry && key.rotation == g.rotation &&
        key.start_param == g.start_param && key.sweep == g.sweep) {
      table_hold_ = it->second;
      return *table_hold_;
    }
  }
  if (cache.size() >= kMaxTables) cache.erase(cache.begin());
  EllipticalArc key = g;
  key.center = Point(0, 0);
  auto table = std::make_shared<EllipseTable>();
  table->build(Element(key, true));
  cache.emplace_back(key, table);
  table_hold_ = std::move(table);
  return *table_hold_;
}

bool PlannedLocus::advance() {
  // The acceleration the current command ends with: the next samples' tick means reach back
  // into it.
  prev_end_accel_ = ff_.inertia_s2 != 0 && current_ && current_->kind != CommandKind::dwell
                        ? accel_at(*current_, profile_, 1)
                        : Point(0, 0);
  while (next_ < commands_.size()) {
    const double d = durations_[next_];
    const Command& c = commands_[next_++];
    if (!(d > 0)) continue;
    current_ = &c;
    // ... and the one the next command starts with (second order only).
    next_start_accel_ = Point(0, 0);
    for (std::size_t j = next_; ff_.inertia_s2 != 0 && j < commands_.size(); ++j) {
      const Command& n = commands_[j];
      if (!(durations_[j] > 0)) continue;
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
            inv_radius_ = 1 / g.radius;
            angle0_ = g.start_angle;
            turn_ = g.sweep >= 0 ? 1.0 : -1.0;
            arc_s_ = 0;
            arc_c_ = std::cos(angle0_);
            arc_sn_ = std::sin(angle0_);
            arc_steps_ = 0;
          } else {
            center_ = g.center;
            table_ = &ellipse_table(g);
            cursor_ = 0;
          }
        },
        c.path.geometry());
    return true;
  }
  return false;
}

template <CommandKind Kind, bool SecondOrder>
inline void PlannedLocus::emit(ScanSample& o, double tau, double s, double v) {
  if constexpr (Kind == CommandKind::dwell) {
    o.x_mm = static_cast<float>(p0_.x());
    o.y_mm = static_cast<float>(p0_.y());
    o.power = 255;  // a lit dwell is a deliberate lit wait
    o.laser = laser_;
    return;
  } else {
    const SpeedProfile& pr = profile_;
    Point p, t, k;
    if constexpr (Kind == CommandKind::arc) {
      // Rotate the previous sample's (cos, sin) by the angle travelled since: a short series
      // instead of a sincos call per sample; exact again every 64 samples and for large steps.
      const double d = turn_ * (s - arc_s_) * inv_radius_;
      if (++arc_steps_ >= 64 || std::abs(d) > 0.5) {
        const double th = angle0_ + turn_ * s / radius_;
        arc_c_ = std::cos(th);
        arc_sn_ = std::sin(th);
        arc_steps_ = 0;
      } else {
        const double d2 = d * d;
        const double cd = 1 - d2 / 2 * (1 - d2 / 12 * (1 - d2 / 30 * (1 - d2 / 56)));
        const double sd = d * (1 - d2 / 6 * (1 - d2 / 20 * (1 - d2 / 42 * (1 - d2 / 72))));
        const double c = arc_c_ * cd - arc_sn_ * sd;
        arc_sn_ = arc_sn_ * cd + arc_c_ * sd;
        arc_c_ = c;
      }
      arc_s_ = s;
      p = center_ + radius_ * Point(arc_c_, arc_sn_);
      t = turn_ * Point(-arc_sn_, arc_c_);
      k = -inv_radius_ * Point(arc_c_, arc_sn_);
    } else if constexpr (Kind == CommandKind::ellipse) {
      table_->frame_at<SecondOrder>(s, cursor_, p, t, k);
      p += center_;
    } else {  // jump, line
      p = p0_ + s * u_;
      t = u_;
      k = Point(0, 0);
    }
    Point x = p + (ff_.lag_s * v) * t;
    if constexpr (SecondOrder) {
      // The second-order term needs the acceleration, which jumps where the profile changes
      // phase: the head sees the command held linearly between samples, so each sample carries
      // the mean acceleration over its own tick (±half a tick around it, reaching into the
      // neighbouring commands) — a step in the command then ramps across the samples with the
      // step's area, centred on it.
      const double half = 0.5 * tick_s_;
      const double lo = std::max(0.0, tau - half), hi = std::min(pr.duration, tau + half);
      const Point acc = ((pr.speed(hi) - pr.speed(lo)) * t + (hi - lo) * (v * v) * k +
                         std::max(0.0, half - tau) * prev_end_accel_ +
                         std::max(0.0, tau + half - pr.duration) * next_start_accel_) /
                        tick_s_;
      x += ff_.inertia_s2 * acc;
    }
    // Power ∝ the path length this tick covers (the sample's laser state holds for the tick
    // ending at it), so the dose per mm is the same at every speed (pulses still land v / f apart).
    const double path = path0_ + s;
    const double tick_speed = (path - last_path_) * inv_tick_;
    last_path_ = path;
    // Integer clamps (conditional moves): the power changes every sample while speeding up.
    int q = power_per_speed_ > 0 ? static_cast<int>(tick_speed * power_per_speed_ + 0.5) : 255;
    q = q < 1 ? 1 : q;
    q = q > 255 ? 255 : q;
    o.power = static_cast<std::uint8_t>(q);
    o.laser = laser_ & (tick_speed >= min_lit_speed_);
    o.x_mm = static_cast<float>(x.x());
    o.y_mm = static_cast<float>(x.y());
  }
}

template <CommandKind Kind, bool SecondOrder>
void PlannedLocus::emit_run(ScanSample* out, std::uint64_t n) {
  if constexpr (Kind == CommandKind::dwell) {
    for (std::uint64_t i = 0; i < n; ++i, ++k_) emit<Kind, SecondOrder>(out[i], 0, 0, 0);
    return;
  }
  // Sample by sample within one phase of the profile (constant acceleration): the arc length
  // and speed are a polynomial in the local time, no branch per sample. Past the profile's end
  // (the job's last partial tick) the path holds its end.
  const SpeedProfile& pr = profile_;
  const double phase_end[4] = {pr.t1, pr.t2, pr.duration, INFINITY};
  const double phase_t0[4] = {0, pr.t1, pr.t2, pr.duration};
  const double phase_s0[4] = {0, pr.s1, pr.s2, pr.length};
  const double phase_v0[4] = {pr.v0, pr.vp, pr.vp, pr.v1};
  const double phase_a[4] = {pr.a, 0, -pr.d, 0};
  std::uint64_t i = 0;
  double tau = static_cast<double>(k_ + 1) * tick_s_ - t0_;
  for (int ph = 0; ph < 4 && i < n; ++ph) {
    const double a = ph == 3 ? 0 : phase_a[ph];
    const double v0 = ph == 3 ? 0 : phase_v0[ph];
    for (; i < n && tau <= phase_end[ph]; ++i, ++k_) {
      const double u = tau - phase_t0[ph];
      emit<Kind, SecondOrder>(out[i], tau, phase_s0[ph] + u * (v0 + 0.5 * a * u),
                              ph == 3 ? pr.v1 : v0 + a * u);
      tau = static_cast<double>(k_ + 2) * tick_s_ - t0_;
    }
  }
}

template <bool SecondOrder>
void PlannedLocus::emit_run(ScanSample* out, std::uint64_t n) {
  switch (kind_) {
    case CommandKind::dwell: return emit_run<CommandKind::dwell, SecondOrder>(out, n);
    case CommandKind::arc: return emit_run<CommandKind::arc, SecondOrder>(out, n);
    case CommandKind::ellipse: return emit_run<CommandKind::ellipse, SecondOrder>(out, n);
    case CommandKind::jump:
    case CommandKind::line: return emit_run<CommandKind::line, SecondOrder>(out, n);
  }
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
    if (ff_.inertia_s2 != 0)
      emit_run<true>(out + written, n);
    else
      emit_run<false>(out + written, n);
    written += static_cast<std::size_t>(n);
  }
  return written;
}

}  // namespace mark

#include "marker/job/device_program.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <variant>

#include "fonts/error.hpp"
#include "fonts/overloaded.hpp"

namespace mark {
namespace {

// Uniform parameter steps along an arc or ellipse arc whose chords deviate from the curve by at
// most `tol`: a chord over Δt of a curve whose second derivative (per unit of the angle
// parameter) is at most R deviates by at most R·Δt²/8, and R ≤ the larger radius.
std::size_t chord_count(const Element& e, double tol_mm) {
  const auto [reach, sweep] = std::visit(
      Overloaded{[](const Line&) { return std::pair{0.0, 0.0}; },
                 [](const CircularArc& a) { return std::pair{a.radius, a.sweep}; },
                 [](const EllipticalArc& a) { return std::pair{std::max(a.rx, a.ry), a.sweep}; }},
      e.geometry());
  if (reach <= 0) return 1;
  const double step = std::sqrt(8 * std::max(tol_mm, 1e-7) / reach);
  return std::max<std::size_t>(1, static_cast<std::size_t>(std::ceil(std::abs(sweep) / step)));
}

// The points at parameters k/n (k = 1 … n) of an arc or ellipse arc, for chords: the angle
// advances by a fixed rotation instead of a sin/cos per point (two-thirds of the conversion's
// time went to sincos), and the last point is the element's exact end. The recurrence drifts by
// about k·1e-16 of the radius: far below the chord tolerance for any n a glyph needs. `start`
// is the element's start point (the caller has it; a circle's first direction comes from it).
// Points are built coordinate by coordinate, not as Eigen expressions: Eigen stored c and s as
// two doubles and read them back as one 16-byte vector, a failed store-to-load forward on every
// chord (a quarter of the conversion's time); the arithmetic, and so every point, is the same.
template <class F>
void for_chord_points(const Element& e, const Point& start, std::size_t n, F&& emit) {
  const auto rotate_from = [&](double c, double s, double step, auto&& place) {
    const double dc = std::cos(step), ds = std::sin(step);
    for (std::size_t k = 1; k < n; ++k) {
      const double c1 = c * dc - s * ds;
      s = s * dc + c * ds;
      c = c1;
      emit(place(c, s));
    }
    emit(e.end());
  };
  std::visit(Overloaded{[&](const Line&) { emit(e.end()); },
                        [&](const CircularArc& a) {
                          const Point u = (start - a.center) / a.radius;
                          rotate_from(u.x(), u.y(), a.sweep / double(n), [&](double c, double s) {
                            return Point(a.center.x() + a.radius * c, a.center.y() + a.radius * s);
                          });
                        },
                        [&](const EllipticalArc& el) {
                          const double rc = std::cos(el.rotation), rs = std::sin(el.rotation);
                          rotate_from(std::cos(el.start_param), std::sin(el.start_param),
                                      el.sweep / double(n), [&](double c, double s) {
                            const double x = el.rx * c, y = el.ry * s;
                            return Point(el.center.x() + (rc * x - rs * y),
                                         el.center.y() + (rs * x + rc * y));
                          });
                        }},
             e.geometry());
}

class Builder {
 public:
  Builder(const DeviceDescription& device, DeviceProgram& out) : device_(device), out_(out) {}

  void jump(const Point& p, double speed) { push(DeviceCommand::jump_to(p.x(), p.y(), speed), false, 0); }

  void mark(const Element& e, double speed) {
    if (e.kind() == ElementKind::line) {
      const Point p = e.end();
      push(DeviceCommand::mark_to(p.x(), p.y(), speed), true, e.length());
      return;
    }
    if (e.kind() == ElementKind::arc && device_.arcs) {
      const auto& a = std::get<CircularArc>(e.geometry());
      check(e.point_at(0.5));  // an arc's bulge can leave the field even when its ends do not
      const Point p = e.end();
      push(DeviceCommand::arc_to(p.x(), p.y(), a.center.x(), a.center.y(), a.sweep, speed), true,
           e.length());
      return;
    }
    const std::size_t n = chord_count(e, device_.chord_tolerance_mm);
    Point prev = e.start();
    if (const auto* a = std::get_if<CircularArc>(&e.geometry())) {
      // Equal steps on a circle give equal chords, 2R·sin(|sweep|/2n): one sine per arc instead
      // of a square root per chord (ink only; the points are the same either way).
      const double chord = 2 * a->radius * std::sin(std::abs(a->sweep) / (2 * double(n)));
      for_chord_points(e, prev, n, [&](const Point& p) {
        push(DeviceCommand::mark_to(p.x(), p.y(), speed), true, chord);
      });
    } else {
      for_chord_points(e, prev, n, [&](const Point& p) {
        push(DeviceCommand::mark_to(p.x(), p.y(), speed), true, (p - prev).norm());
        prev = p;
      });
    }
    out_.chords += n;
  }

  void laser_off_line(const Element& e, double speed) {
    // Blanking lines are straight; anything else unlit is flattened like a lit curve.
    const std::size_t n = e.kind() == ElementKind::line ? 1 : chord_count(e, device_.chord_tolerance_mm);
    for_chord_points(e, e.start(), n, [&](const Point& p) { jump(p, speed); });
  }

  void dwell(double seconds, bool laser) { push(DeviceCommand::dwell_for(seconds, laser), false, 0); }
  void pen(std::uint16_t index) { push(DeviceCommand::select_pen(index), false, 0); }

 private:
  // The test runs for every point, inline; the refusal is out of line so the hot path stays
  // small (|v| ≤ half is false for NaN; infinities are above half).
  void check(const Point& p) const {
    if (std::abs(p.x()) <= half_ && std::abs(p.y()) <= half_) [[likely]]
      return;
    refuse(p);
  }
  [[noreturn, gnu::noinline, gnu::cold]] void refuse(const Point& p) const {
    const double half = device_.field_mm / 2;
    char msg[240];
    std::snprintf(msg, sizeof msg,
                  "%s: command %zu goes to (%.4f, %.4f) mm, outside the field ±%.3f mm; nothing "
                  "was sent",
                  device_.name.c_str(), out_.commands.size(), p.x(), p.y(), half);
    throw DeviceFaultError({FaultCategory::out_of_field, msg, out_.commands.size()});
  }
  void push(const DeviceCommand& c, bool lit, double length) {
    if (c.op == DeviceOp::jump || c.op == DeviceOp::mark || c.op == DeviceOp::arc)
      check(Point(c.x_mm, c.y_mm));
    out_.commands.push_back(c);
    if (lit) out_.lit_length_mm += length;
    out_.ink_after.push_back(out_.lit_length_mm);
  }

  const DeviceDescription& device_;
  DeviceProgram& out_;
  // Clamped so that an infinite point is refused even by an unbounded field.
  const double half_ = std::min(device_.field_mm / 2, std::numeric_limits<double>::max());
};

}  // namespace

Plan plan_for_device(const Figure& figure, const Pen& pen, StrokeOrder order) {
  // Look-ahead and feed-forward shape the 10 µs samples themselves; a board with its own clock
  // ramps its own speeds and drives its servo itself.
  if (pen.lookahead || pen.feed_forward())
    throw InputError("look-ahead and feed-forward need a sample-level device: a command-level "
                     "board runs its own clock and speed ramps");
  Pen p = pen;
  if (p.corner == CornerStrategy::delays) p.corner = CornerStrategy::none;  // the board waits
  Plan plan = plan_figure(figure, p, order);
  plan.pen = pen;  // the delays the board will apply, reported with the plan
  return plan;
}

DevicePen device_pen(const Pen& pen, const LaserSettings& laser, DeviceLevel level) {
  DevicePen d;
  d.mark_speed_mm_s = pen.mark_speed_mm_s;
  d.jump_speed_mm_s = pen.jump_speed_mm_s;
  d.laser = laser;
  if (level == DeviceLevel::samples) return d;  // the host's delay line and dwells do it
  d.laser_on_delay_s = pen.laser_on_delay_s;
  d.laser_off_delay_s = pen.laser_off_delay_s;
  if (pen.corner == CornerStrategy::delays) {
    d.jump_delay_s = pen.jump_delay_s;
    d.mark_delay_s = std::max(pen.mark_delay_s, pen.laser_off_delay_s);
    d.polygon_delay_s = pen.polygon_delay_s;
  }
  return d;
}

DeviceProgram device_program(const Plan& plan, const LaserSettings& laser,
                             const DeviceDescription& device) {
  DeviceProgram out;
  out.pen = device_pen(plan.pen, laser, DeviceLevel::commands);
  // Room for every chord up front: a reallocation of tens of thousands of commands costs more
  // than this count.
  std::size_t expected = plan.commands.size() + 1;
  for (const Command& c : plan.commands)
    if (c.kind == CommandKind::arc || c.kind == CommandKind::ellipse)
      expected += chord_count(c.path, device.chord_tolerance_mm) - 1;
  out.commands.reserve(expected);
  out.ink_after.reserve(expected + 1);
  Builder b(device, out);
  b.pen(0);
  for (const Command& c : plan.commands) {
    switch (c.role) {
      case CommandRole::stroke:
        if (c.kind == CommandKind::dwell) {
          b.dwell(c.dwell_ticks * plan.pen.tick_s, c.laser());
        } else {
          b.mark(c.path, c.speed_mm_s);
        }
        break;
      case CommandRole::jump:
        b.jump(c.end(), 0);
        break;
      case CommandRole::run_in:
      case CommandRole::run_out:
      case CommandRole::blank_join:
        b.laser_off_line(c.path, c.speed_mm_s);
        break;
      case CommandRole::delay:
        break;  // jump, mark and polygon delays are the board's job (DevicePen)
    }
  }
  return out;
}

double ink_fraction(const DeviceProgram& program, std::uint64_t done) {
  if (program.lit_length_mm <= 0) return done >= program.commands.size() ? 1.0 : 0.0;
  const std::size_t i = static_cast<std::size_t>(
      std::min<std::uint64_t>(done, program.ink_after.size() - 1));
  return program.ink_after[i] / program.lit_length_mm;
}

}  // namespace mark

#include "marker/job/device_program.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <limits>
#include <span>
#include <variant>

#include "base/error.hpp"
#include "marker/geometry/flatten.hpp"
#include "marker/job/timed_moves.hpp"

namespace mark {
namespace {

// The larger of two reaches, NaN if either is (std::max drops a NaN in its second argument).
double worst(double a, double b) { return a != a || a > b ? a : b; }

// The commands that become chords (their chord counts are kept in ProgramCount).
bool is_curve(const Command& c) { return c.kind == CommandKind::arc || c.kind == CommandKind::ellipse; }

class Builder {
 public:
  Builder(const DeviceDescription& device, DeviceProgram& out) : device_(device), out_(out) {}

  void jump(double x, double y, double speed) {
    check(x, y);
    out_.commands.push_back(DeviceCommand::jump_to(x, y, speed));
  }

  // `n`: the element's chord count (chord_count), 1 for a line.
  void mark(const Element& e, double speed, std::size_t n) {
    if (e.kind() == ElementKind::arc && device_.arcs) {
      const auto& a = std::get<CircularArc>(e.geometry());
      const Point mid = e.point_at(0.5);  // an arc's bulge can leave the field when its ends do not
      check(mid.x(), mid.y());
      const Point p = e.end();
      check(p.x(), p.y());
      out_.commands.push_back(
          DeviceCommand::arc_to(p.x(), p.y(), a.center.x(), a.center.y(), a.sweep, speed));
      return;
    }
    for_each_piece_end(e, n, [&](double x, double y) {
      check(x, y);
      out_.commands.push_back(DeviceCommand::mark_to(x, y, speed));
    });
    if (e.kind() != ElementKind::line) out_.chords += n;
  }

  // Blanking lines are straight; anything else unlit is flattened like a lit curve.
  void laser_off_line(const Element& e, double speed, std::size_t n) {
    for_each_piece_end(e, n, [&](double x, double y) { jump(x, y, speed); });
  }

  void dwell(double seconds, bool laser) {
    out_.commands.push_back(DeviceCommand::dwell_for(seconds, laser));
  }
  void pen(std::uint16_t index) { out_.commands.push_back(DeviceCommand::select_pen(index)); }

 private:
  // The test runs for every point, inline; the refusal is out of line so the hot path stays
  // small (|v| ≤ half is false for NaN; infinities are above half).
  void check(double x, double y) const {
    if (std::abs(x) <= half_ && std::abs(y) <= half_) [[likely]]
      return;
    refuse(x, y);
  }
  [[noreturn, gnu::noinline, gnu::cold]] void refuse(double x, double y) const {
    refuse_outside_field(device_, x, y, out_.commands.size());
  }

  const DeviceDescription& device_;
  DeviceProgram& out_;
  // Clamped so that an infinite point is refused even by an unbounded field.
  const double half_ = std::min(device_.field_mm / 2, std::numeric_limits<double>::max());
};

}  // namespace

void refuse_outside_field(const DeviceDescription& device, double x, double y, std::size_t command) {
  char msg[240];
  std::snprintf(msg, sizeof msg,
                "%s: command %zu goes to (%.4f, %.4f) mm, outside the field ±%.3f mm; nothing "
                "was sent",
                device.name.c_str(), command, x, y, device.field_mm / 2);
  throw DeviceFaultError({FaultCategory::out_of_field, msg, command});
}

Plan plan_for_device(const Figure& figure, const Pen& pen, StrokeOrder order) {
  // Look-ahead and feed-forward shape the samples themselves: the board gets them as timed
  // moves (timed_moves.hpp), from the plan a sample-level device would get. The board starts
  // at the field centre, the locus's home.
  if (timed_on_board(pen)) return plan_figure(figure, pen, order);
  Pen p = pen;
  if (p.corner == CornerStrategy::delays) p.corner = CornerStrategy::none;  // the board waits
  p.whole_tick_speeds = false;  // the board's own ticks; one speed word per pen
  Plan plan = plan_figure(figure, p, order);
  plan.pen = pen;  // the delays the board will apply, reported with the plan
  return plan;
}

DevicePen device_pen(const Pen& pen, const LaserSettings& laser, DeviceLevel level) {
  DevicePen d;
  d.mark_speed_mm_s = pen.mark_speed_mm_s;
  d.jump_speed_mm_s = pen.jump_speed_mm_s;
  d.laser = laser;
  // The host's delay line and dwells do it.
  if (level == DeviceLevel::samples || timed_on_board(pen)) return d;
  d.laser_on_delay_s = pen.laser_on_delay_s;
  d.laser_off_delay_s = pen.laser_off_delay_s;
  if (pen.corner == CornerStrategy::delays) {
    d.jump_delay_s = pen.jump_delay_s;
    d.mark_delay_s = std::max(pen.mark_delay_s, pen.laser_off_delay_s);
    d.polygon_delay_s = pen.polygon_delay_s;
  }
  return d;
}

ProgramCount count_program(const Plan& plan, const DeviceDescription& device, std::size_t begin,
                           std::size_t end) {
  // One pass over the plan: it is megabytes (40 rows: 23 120 commands of 192 bytes), and
  // reading it is most of this pass's 75 µs. Curves get their chord counts (a square root and
  // a division each), kept for the conversion. The reach bounds |x| and |y| of every point the
  // conversion can emit: a line's ends, an arc's whole circle, an ellipse's circumscribed
  // circle — no sines needed. The running maximum lives in memory (the chord counts call out),
  // so it is only written when it grows: written on every command, each command waited on the
  // last one's store (113 µs).
  ProgramCount n;
  end = std::min(end, plan.commands.size());
  begin = std::min(begin, end);
  n.commands = end - begin;
  double reach = 0;
  bool nan = false;
  for (const Command& c : std::span(plan.commands).subspan(begin, end - begin)) {
    if (is_curve(c))
      n.commands += n.chords.emplace_back(chord_count(c.path, device.chord_tolerance_mm)) - 1;
    const Element::Geometry& g = c.path.geometry();
    double r;
    if (const Line* l = std::get_if<Line>(&g)) {
      r = worst(worst(std::abs(l->start.x()), std::abs(l->start.y())),
                worst(std::abs(l->end.x()), std::abs(l->end.y())));
    } else if (const CircularArc* a = std::get_if<CircularArc>(&g)) {
      r = worst(std::abs(a->center.x()), std::abs(a->center.y())) + std::abs(a->radius);
    } else {
      const auto& e = std::get<EllipticalArc>(g);
      r = worst(std::abs(e.center.x()), std::abs(e.center.y())) + worst(std::abs(e.rx), std::abs(e.ry));
    }
    if (r > reach) [[unlikely]] reach = r;
    if (r != r) [[unlikely]] nan = true;
  }
  // A margin of 1e-9 of the field for the rounding of the chord recurrence (about 1e-16 of a
  // radius per chord).
  n.inside_field = !nan && reach <= device.field_mm / 2 * (1 - 1e-9);
  return n;
}

void convert_program(const Plan& plan, const DeviceDescription& device, const ProgramCount& count,
                     DeviceProgram& out, const std::function<void(std::size_t)>& progress,
                     std::size_t every) {
  Builder b(device, out);
  b.pen(0);
  std::size_t next_curve = 0, reported = 0;
  for (const Command& c : plan.commands) {
    const std::size_t n = is_curve(c) ? count.chords[next_curve++] : 1;
    switch (c.role) {
      case CommandRole::stroke:
        if (c.kind == CommandKind::dwell) {
          b.dwell(c.dwell_ticks * plan.pen.tick_s, c.laser());
        } else {
          b.mark(c.path, c.speed_mm_s, n);
        }
        break;
      case CommandRole::jump:
        b.laser_off_line(c.path, 0, 1);
        break;
      case CommandRole::run_in:
      case CommandRole::run_out:
      case CommandRole::blank_join:
        b.laser_off_line(c.path, c.speed_mm_s, n);
        break;
      case CommandRole::delay:
        break;  // jump, mark and polygon delays are the board's job (DevicePen)
    }
    if (out.commands.size() - reported >= every) [[unlikely]] {
      reported = out.commands.size();
      if (progress) progress(reported);
    }
  }
  if (progress) progress(out.commands.size());
}

DeviceProgram device_program(const Plan& plan, const LaserSettings& laser,
                             const DeviceDescription& device) {
  if (timed_on_board(plan.pen)) return timed_program(plan, laser, device);
  DeviceProgram out;
  out.pen = device_pen(plan.pen, laser, DeviceLevel::commands);
  // Room for every chord up front: a reallocation of tens of thousands of commands costs more
  // than the count.
  const ProgramCount count = count_program(plan, device);
  out.commands.reserve(count.commands + 1);
  convert_program(plan, device, count, out, {}, std::numeric_limits<std::size_t>::max());
  return out;
}

double lit_length_mm(const DeviceProgram& program, std::uint64_t done) {
  // Every command starts where the previous one ended, the first at the field centre.
  double lit = 0, x = 0, y = 0;
  const std::size_t n = static_cast<std::size_t>(std::min<std::uint64_t>(done, program.commands.size()));
  for (std::size_t i = 0; i < n; ++i) {
    const DeviceCommand& c = program.commands[i];
    switch (c.op) {
      case DeviceOp::mark: lit += std::hypot(c.x_mm - x, c.y_mm - y); break;
      case DeviceOp::arc: lit += std::abs(c.sweep_rad) * std::hypot(x - c.cx_mm, y - c.cy_mm); break;
      case DeviceOp::jump:
      case DeviceOp::dwell:
      case DeviceOp::pen: break;
    }
    if (c.op == DeviceOp::jump || c.op == DeviceOp::mark || c.op == DeviceOp::arc) x = c.x_mm, y = c.y_mm;
  }
  return lit;
}

double ink_fraction(const DeviceProgram& program, std::uint64_t done) {
  const double all = lit_length_mm(program);
  if (all <= 0) return done >= program.commands.size() ? 1.0 : 0.0;
  return lit_length_mm(program, done) / all;
}

}  // namespace mark

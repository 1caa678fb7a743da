#include "marker/plan/plan.hpp"

#include <algorithm>
#include <atomic>
#include <cmath>

#include "marker/plan/input_shaper.hpp"
#include "marker/plan/plan_builder.hpp"
#include "marker/plan/speed_plan.hpp"

namespace mark {

bool PlanBuilder::jump_to(const Point& target) {
  if ((target - at).norm() <= kJoinTolerance_mm) return false;
  move(Command::jump(at, target, pen.jump_speed_mm_s));
  return true;
}

Command PlanBuilder::mark(const Element& e, double speed_mm_s, CommandRole role) {
  if (e.kind() != ElementKind::ellipse) return Command::mark(e, speed_mm_s, role);
  const auto& g = std::get<EllipticalArc>(e.geometry());
  for (const auto& [k, len] : ellipse_lengths)
    if (k.rx == g.rx && k.ry == g.ry && k.start_param == g.start_param && k.sweep == g.sweep)
      return Command::mark(e, speed_mm_s, role, len);
  Command c = Command::mark(e, speed_mm_s, role);
  ellipse_lengths.emplace_back(g, c.length);
  return c;
}

Point PlanBuilder::velocity() const {
  if (out.empty() || out.back().kind == CommandKind::dwell) return {0, 0};
  return out.back().speed_mm_s * out.back().path.tangent_at(1.0);
}

double turn_angle_rad(const Element& a, const Element& b) {
  const double c = a.tangent_at(1.0).dot(b.tangent_at(0.0));
  return std::acos(std::clamp(c, -1.0, 1.0));
}

Box Plan::bounds() const {
  Box box;
  box.add(home);
  const InputShaper shaper = design_input_shaper(pen);
  for (const Command& c : commands) {
    Box b = c.path.bounds();
    if ((pen.feed_forward() || shaper.active()) && c.kind != CommandKind::dwell) {
      // The command leads the path by lag·v + inertia·a at most: speed and the larger of the
      // tangential and centripetal rates (both bounded by the plan). An input shaper's command
      // is a weighted mean of such commands, inside the same box.
      const double a = std::max({c.accel_mm_s2, c.decel_mm_s2, pen.curve_accel_mm_s2});
      const double lead = std::abs(shaper.lag_s) * c.speed_mm_s + std::abs(shaper.inertia_s2) * 2 * a;
      b.min -= Point(lead, lead);
      b.max += Point(lead, lead);
    }
    box.add(b);
  }
  return box;
}

double Plan::duration_s() const {
  double t = 0;
  for (const Command& c : commands)
    t += c.kind == CommandKind::dwell ? c.dwell_ticks * pen.tick_s : c.move_duration_s();
  return t;
}

std::size_t Plan::count(CommandRole role) const {
  return static_cast<std::size_t>(std::count_if(
      commands.begin(), commands.end(), [&](const Command& c) { return c.role == role; }));
}

namespace {
std::atomic<std::uint64_t> plans{0};
}  // namespace

std::uint64_t plans_made() { return plans.load(std::memory_order_relaxed); }
void count_plan() { plans.fetch_add(1, std::memory_order_relaxed); }

Plan plan_strokes(const std::vector<Stroke>& ordered_strokes, const Pen& pen, const Point& home) {
  count_plan();
  Plan plan;
  plan.pen = pen;
  plan.home = home;
  plan.strokes = ordered_strokes.size();
  plan.jump_length_mm = jump_length_mm(ordered_strokes, home);
  PlanBuilder b{plan.pen, plan.commands, home, {}};
  for (const Stroke& s : ordered_strokes) {
    switch (pen.corner) {
      case CornerStrategy::none: plan_stroke_plain(b, s); break;
      case CornerStrategy::delays: plan_stroke_delays(b, s); break;
      case CornerStrategy::blanking: plan_stroke_blanking(b, s); break;
    }
  }
  if (pen.lookahead || pen.feed_forward()) plan_speeds(plan.commands, plan.pen);
  return plan;
}

Plan plan_figure(const Figure& figure, const Pen& pen, StrokeOrder order, const Point& home) {
  return plan_strokes(order_strokes(strokes_of(figure), order, home), pen, home);
}

}  // namespace mark

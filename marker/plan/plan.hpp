#pragma once
// The planner: a Figure's strokes → drawing commands for one pen. Strokes are ordered (glyph
// order or shortest jumps), then each is turned into commands by the pen's corner strategy.
#include <cstddef>
#include <vector>

#include "marker/layout/figure.hpp"
#include "marker/plan/command.hpp"
#include "marker/plan/pen.hpp"
#include "marker/plan/stroke.hpp"
#include "marker/plan/stroke_order.hpp"

namespace mark {

struct Plan {
  std::vector<Command> commands;
  Pen pen;
  Point home{0, 0};            // where the mirrors rest before the first command
  std::size_t strokes = 0;
  double jump_length_mm = 0;   // home → strokes, stroke end → next stroke start (straight)

  // Everything the mirrors are commanded to pass: home, lit elements, jumps, blanking lines.
  Box bounds() const;
  // Commanded time: Σ length/speed over moves plus dwell ticks (the locus rounds it to ticks).
  double duration_s() const;
  std::size_t count(CommandRole role) const;
};

Plan plan_strokes(const std::vector<Stroke>& ordered_strokes, const Pen& pen,
                  const Point& home = Point(0, 0));
Plan plan_figure(const Figure& figure, const Pen& pen, StrokeOrder order = StrokeOrder::glyph,
                 const Point& home = Point(0, 0));
// Plans this process has made (plan_strokes calls and Replanner updates): tests and benchmarks
// hold a command to one plan per mark with it.
std::uint64_t plans_made();
void count_plan();  // for the planners (plan_strokes, Replanner)

// Turn angle φ ∈ [0, π] between the end direction of `a` and the start direction of `b`
// (0 = straight on, π = reversal).
double turn_angle_rad(const Element& a, const Element& b);

}  // namespace mark

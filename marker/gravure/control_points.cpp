#include "marker/gravure/control_points.hpp"

#include <algorithm>

namespace mark {
namespace {

constexpr double kWhiteBelow = 0.01;   // block 94: total density under 1 %
constexpr double kChannelAbove = 0.90;  // claims 11–12: above 90 % entry and exit stay below

// Keep the centre a quarter of the span away from entry and exit.
double inside(double centre, double entry, double exit) {
  const double margin = (exit - entry) / 4;
  return std::clamp(centre, entry + margin, exit - margin);
}

}  // namespace

std::string_view to_string(CellKind kind) {
  switch (kind) {
    case CellKind::white: return "white";
    case CellKind::single: return "single";
    case CellKind::channel: return "channel";
    case CellKind::split: return "split";
  }
  return "?";
}

double density_centre(const float* v, int n, double from, double to) {
  const double part = (to - from) / n;
  double total = 0;
  for (int i = 0; i < n; ++i) total += v[i];
  if (!(total > 0)) return (from + to) / 2;
  const double half = total / 2;
  // The running density reaches half at `first` and stays there (over empty parts) up to `last`.
  double first = from, last = to, run = 0;
  for (int i = 0; i < n; ++i) {
    if (v[i] > 0 && run + v[i] >= half) {
      first = from + part * (i + (half - run) / v[i]);
      break;
    }
    run += v[i];
  }
  run = 0;
  for (int i = n - 1; i >= 0; --i) {
    if (v[i] > 0 && run + v[i] >= half) {
      last = from + part * (i + 1 - (half - run) / v[i]);
      break;
    }
    run += v[i];
  }
  return (first + last) / 2;
}

CellPlan plan_cell(const CellValues& cell, const GravureSetup& setup) {
  const CellSetup& s = cell.line_work ? setup.lw : setup.ct;
  const auto& d = cell.density;
  const double total = (d[0] + d[1] + d[2] + d[3]) / 4.0;
  CellPlan plan;
  auto add = [&plan](double x, double depth) { plan.points[plan.count++] = {x, depth}; };

  if (total < kWhiteBelow) {
    plan.kind = CellKind::white;
    add(0.5, -setup.lift_um);
    return plan;
  }

  if (d[0] > d[1] + d[2] && d[3] > d[1] + d[2]) {
    plan.kind = CellKind::split;
    const double da = (d[0] + d[1]) / 2.0, db = (d[2] + d[3]) / 2.0;
    const double exit_a = 0.5 * da, entry_b = 1 - 0.5 * db;  // D1 and D3, proportional to density
    add(0, s.channel_depth(d[0]));
    add(inside(density_centre(&d[0], 2, 0, 0.5), 0, exit_a), s.full_cell_depth(da));
    add(exit_a, 0);
    add(entry_b, 0);
    add(inside(density_centre(&d[2], 2, 0.5, 1), entry_b, 1), s.full_cell_depth(db));
    add(1, s.channel_depth(d[3]));
    return plan;
  }

  const double centre = density_centre(d.data(), 4, 0, 1);
  const double depth = s.full_cell_depth(total);
  if (total > kChannelAbove) {
    plan.kind = CellKind::channel;
    add(0, s.channel_depth(d[0]));
    add(inside(centre, 0, 1), depth);
    add(1, s.channel_depth(d[3]));
    return plan;
  }
  plan.kind = CellKind::single;
  const double shift = std::max(0.0, total / 2 - centre) - std::max(0.0, centre + total / 2 - 1);
  const double entry = centre - total / 2 + shift, exit = centre + total / 2 + shift;
  add(entry, 0);
  add(inside(centre, entry, exit), depth);
  add(exit, 0);
  return plan;
}

}  // namespace mark

#include "marker/cnc/machine_envelope.hpp"

#include <cmath>
#include <cstdio>
#include <string>

#include "base/error.hpp"

namespace mark {
namespace {

std::string mm(double v) {
  char buf[48];
  std::snprintf(buf, sizeof buf, std::abs(v) < 1e9 ? "%.3f" : "%.4g", v);
  return buf;
}

// The part of a circular arc move from `from` to m.end about m.center, as a box.
Box arc_box(const Point& from, const ToolMove& m) {
  const Point to(m.end.x(), m.end.y());
  const Point c = m.center;
  const double r = (from - c).norm();
  const double a0 = std::atan2(from.y() - c.y(), from.x() - c.x());
  double sweep = std::atan2(to.y() - c.y(), to.x() - c.x()) - a0;
  if (m.ccw && sweep <= 0) sweep += 2 * M_PI;
  if (!m.ccw && sweep >= 0) sweep -= 2 * M_PI;
  return Element::arc(c, r, a0, sweep).bounds();
}

}  // namespace

double CutFootprint::radius_at(double z_mm) const {
  if (v_half_angle_rad > 0) return std::max(0.0, -z_mm) * std::tan(v_half_angle_rad);
  return tool_radius_mm;
}

ToolpathExtent toolpath_extent(const Toolpath& toolpath, const CutFootprint& footprint) {
  ToolpathExtent ext;
  std::optional<Eigen::Vector3d> at;
  const auto disc = [](const Point& c, double r) {
    Box b;
    b.add(c - Point(r, r));
    b.add(c + Point(r, r));
    return b;
  };
  for (const ToolMove& m : expand_moves(toolpath)) {
    const Point to(m.end.x(), m.end.y());
    Box path;
    path.add(to);
    if (at) path.add(Point(at->x(), at->y()));
    if (m.kind == MoveKind::arc && at) path.add(arc_box(Point(at->x(), at->y()), m));
    ext.moves.add(path);
    const bool cuts = m.kind != MoveKind::rapid && (m.end.z() < 0 || (at && at->z() < 0));
    if (cuts && at) {
      // A straight move's footprint lies within its ends' (the depth, and with it a V-bit's
      // radius, changes linearly); an arc stays at one height.
      if (m.kind == MoveKind::arc) {
        Box b = path;
        const double r = footprint.radius_at(m.end.z());
        b.min -= Point(r, r);
        b.max += Point(r, r);
        ext.cuts.add(b);
      } else {
        ext.cuts.add(disc(Point(at->x(), at->y()), footprint.radius_at(at->z())));
        ext.cuts.add(disc(to, footprint.radius_at(m.end.z())));
      }
    }
    at = m.end;
  }
  return ext;
}

void require_within(const ToolpathExtent& ext, const MachineEnvelope& env, const char* remedy) {
  if (env.stock && !ext.cuts.empty() && !env.stock->contains(ext.cuts, 1e-9)) {
    const Box& s = *env.stock;
    const struct {
      double by;
      const char* side;
    } sides[] = {{s.min.x() - ext.cuts.min.x(), "left"},
                 {ext.cuts.max.x() - s.max.x(), "right"},
                 {s.min.y() - ext.cuts.min.y(), "bottom"},
                 {ext.cuts.max.y() - s.max.y(), "top"}};
    std::string left;
    for (const auto& side : sides)
      if (side.by > 1e-9) left += std::string(left.empty() ? "" : ", ") + "at the " + side.side + " by " + mm(side.by) + " mm";
    throw InputError("the cuts leave the stock " + left + ": they span x " + mm(ext.cuts.min.x()) + " to " +
                     mm(ext.cuts.max.x()) + " mm, y " + mm(ext.cuts.min.y()) + " to " + mm(ext.cuts.max.y()) +
                     " mm (tool footprint included); the --stock is x " + mm(s.min.x()) + " to " + mm(s.max.x()) +
                     " mm, y " + mm(s.min.y()) + " to " + mm(s.max.y()) + " mm; " + remedy);
  }
  const double w = ext.moves.width(), h = ext.moves.height();
  if (w > env.travel_x_mm + 1e-9 || h > env.travel_y_mm + 1e-9)
    throw InputError("the program spans " + mm(w) + " x " + mm(h) + " mm (x " + mm(ext.moves.min.x()) + " to " +
                     mm(ext.moves.max.x()) + ", y " + mm(ext.moves.min.y()) + " to " + mm(ext.moves.max.y()) +
                     " mm), " + (w > env.travel_x_mm + 1e-9 ? mm(w - env.travel_x_mm) + " mm more in x" : mm(h - env.travel_y_mm) + " mm more in y") +
                     " than the --travel " + mm(env.travel_x_mm) + " x " + mm(env.travel_y_mm) + " mm allows; " + remedy);
}

}  // namespace mark

#include "marker/cnc/toolpath.hpp"

#include <Eigen/Geometry>
#include <optional>

#include "fonts/overloaded.hpp"

namespace mark {

ToolMove place_move(const ToolMove& move, const SubprogramCall& call) {
  const Eigen::Rotation2Dd r(call.rotation_rad);
  ToolMove m = move;
  const Point xy = call.origin + r * Point(move.end.x(), move.end.y());
  m.end = {xy.x(), xy.y(), move.end.z()};
  m.center = call.origin + r * move.center;  // a rotation keeps the turning sense: ccw unchanged
  return m;
}

std::vector<ToolMove> expand_moves(const Toolpath& toolpath) {
  std::vector<ToolMove> out;
  for (const ToolStep& step : toolpath.steps)
    std::visit(Overloaded{[&](const ToolMove& m) { out.push_back(m); },
                          [&](const SubprogramCall& c) {
                            for (const ToolMove& m : toolpath.subs[c.sub].body)
                              out.push_back(place_move(m, c));
                          }},
               step);
  return out;
}

RapidTravel rapid_travel(const Toolpath& toolpath) {
  RapidTravel t;
  std::optional<Eigen::Vector3d> at;
  bool cutting = false;
  for (const ToolMove& m : expand_moves(toolpath)) {
    if (m.kind == MoveKind::rapid && at) {
      if (cutting) t.xy_mm += (m.end.head<2>() - at->head<2>()).norm();
      if (at->z() < 0 && m.end.z() > at->z()) ++t.retracts;
    }
    cutting = cutting || (m.kind != MoveKind::rapid && m.end.z() < 0);
    at = m.end;
  }
  return t;
}

}  // namespace mark

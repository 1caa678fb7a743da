#include "marker/cnc/toolpath.hpp"

#include <Eigen/Geometry>

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

}  // namespace mark

#include "marker/head/lag_program.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <string>

#include "base/error.hpp"

namespace mark {
namespace {

void check_device(const LagPattern& pattern, const DeviceDescription& device) {
  const double half = device.field_mm / 2;
  const Vec2 lo = pattern.min(), hi = pattern.max();
  std::ostringstream m;
  if (lo.x < -half || lo.y < -half || hi.x > half || hi.y > half)
    m << "lag pattern: its lines reach (" << lo.x << ", " << lo.y << ") .. (" << hi.x << ", " << hi.y
      << ") mm, outside the " << device.field_mm << " mm field of " << device.name;
  else if (device.max_speed_mm_s > 0 && pattern.fastest_mm_s() > device.max_speed_mm_s)
    m << "lag pattern: its fastest line runs at " << pattern.fastest_mm_s() << " mm/s; " << device.name
      << " marks at most " << device.max_speed_mm_s << " mm/s";
  if (!m.str().empty()) throw InputError(m.str());
}

}  // namespace

LagProgram lag_pattern_program(const LagPattern& pattern, const LaserSettings& laser,
                               const DeviceDescription& device) {
  check_device(pattern, device);
  LagProgram p;
  p.header.name = "lag pattern";
  p.header.field_mm = device.field_mm;
  const double fastest = pattern.fastest_mm_s();
  for (double v : pattern.speeds_mm_s) {
    DevicePen pen;  // every delay zero
    pen.mark_speed_mm_s = v;
    pen.laser = laser;
    pen.laser.power_pct = laser.power_pct * v / fastest;
    p.header.pens.push_back(pen);
  }
  auto dwell = [&](double seconds) {
    const double longest = device.max_dwell_s > 0 ? device.max_dwell_s : seconds;
    const auto pieces = static_cast<int>(std::ceil(seconds / longest - 1e-9));
    for (int i = 0; i < pieces; ++i) p.commands.push_back(DeviceCommand::dwell_for(seconds / pieces, false));
  };
  int selected = -1;
  // One lit path from rest: a jump, the settling dwell, the marks at the speed's pen, a dwell.
  auto path = [&](double speed_mm_s, const std::vector<Vec2>& points) {
    const auto pen = static_cast<int>(std::find(pattern.speeds_mm_s.begin(), pattern.speeds_mm_s.end(), speed_mm_s) -
                                      pattern.speeds_mm_s.begin());
    if (pen == static_cast<int>(pattern.speeds_mm_s.size()))
      throw InputError("lag pattern: a corner's speed " + std::to_string(speed_mm_s) + " mm/s is none of its lines'");
    if (pen != selected) p.commands.push_back(DeviceCommand::select_pen(static_cast<std::uint16_t>(pen)));
    selected = pen;
    p.commands.push_back(DeviceCommand::jump_to(points.front().x, points.front().y));
    dwell(kLagJumpSettle_s);
    for (std::size_t i = 1; i < points.size(); ++i) p.commands.push_back(DeviceCommand::mark_to(points[i].x, points[i].y));
    dwell(kLagAfterLine_s);
    p.header.lit_paths.push_back(points);
  };
  for (const LagLine& l : pattern.lines) path(l.speed_mm_s, {l.start, l.end});
  for (const LagCorner& c : pattern.corners) path(c.speed_mm_s, {c.start, c.corner, c.end});
  return p;
}

}  // namespace mark

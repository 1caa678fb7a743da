#include "marker/head/lag_program.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

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
  for (const LagLine& l : pattern.lines) {
    const auto pen = static_cast<int>(std::find(pattern.speeds_mm_s.begin(), pattern.speeds_mm_s.end(), l.speed_mm_s) -
                                      pattern.speeds_mm_s.begin());
    if (pen != selected) p.commands.push_back(DeviceCommand::select_pen(static_cast<std::uint16_t>(pen)));
    selected = pen;
    p.commands.push_back(DeviceCommand::jump_to(l.start.x, l.start.y));
    dwell(kLagJumpSettle_s);
    p.commands.push_back(DeviceCommand::mark_to(l.end.x, l.end.y));
    dwell(kLagAfterLine_s);
    p.header.lit_paths.push_back({l.start, l.end});
  }
  return p;
}

}  // namespace mark

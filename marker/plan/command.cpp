#include "marker/plan/command.hpp"

#include "marker/plan/speed_profile.hpp"

namespace mark {

double Command::move_duration_s() const {
  if (kind == CommandKind::dwell || !(length > 0)) return 0;
  if (!planned()) return length / speed_mm_s;
  return SpeedProfile::make(length, entry_speed_mm_s, exit_speed_mm_s, speed_mm_s, accel_mm_s2,
                            decel_mm_s2)
      .duration;
}

Command Command::jump(const Point& from, const Point& to, double speed_mm_s) {
  return {CommandKind::jump, CommandRole::jump, Element::line(from, to, false), speed_mm_s, 0,
          (to - from).norm()};
}

Command Command::mark(const Element& element, double speed_mm_s, CommandRole role) {
  return mark(element, speed_mm_s, role, element.length());
}

Command Command::mark(const Element& element, double speed_mm_s, CommandRole role,
                      double length_mm) {
  static constexpr CommandKind kinds[] = {CommandKind::line, CommandKind::arc,
                                          CommandKind::ellipse};
  return {kinds[static_cast<int>(element.kind())], role, element, speed_mm_s, 0, length_mm};
}

Command Command::dwell(const Point& at, std::uint32_t ticks, bool laser) {
  return {CommandKind::dwell, CommandRole::delay, Element::line(at, at, laser), 0, ticks, 0};
}

std::string_view to_string(CommandKind kind) {
  switch (kind) {
    case CommandKind::jump: return "jump";
    case CommandKind::line: return "line";
    case CommandKind::arc: return "arc";
    case CommandKind::ellipse: return "ellipse";
    case CommandKind::dwell: return "dwell";
  }
  return "?";
}

std::string_view to_string(CommandRole role) {
  switch (role) {
    case CommandRole::stroke: return "stroke";
    case CommandRole::jump: return "jump";
    case CommandRole::run_in: return "run-in";
    case CommandRole::run_out: return "run-out";
    case CommandRole::blank_join: return "blank-join";
    case CommandRole::delay: return "delay";
  }
  return "?";
}

}  // namespace mark

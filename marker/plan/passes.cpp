#include "marker/plan/passes.hpp"

#include <algorithm>

namespace mark {

void repeat_passes(Plan& plan, int passes) {
  if (passes <= 1 || plan.commands.empty()) return;
  const std::vector<Command> one = plan.commands;
  // A pass opens with the jump from home; later passes jump there from where the last ended.
  const bool opens_with_jump = one.front().kind == CommandKind::jump;
  const Point entry = opens_with_jump ? one.front().end() : one.front().start();
  const auto first_mark = opens_with_jump ? one.begin() + 1 : one.begin();
  // Jump length counts stroke ends to stroke starts (plan.hpp): per further pass, the way from
  // the last stroke's end back to the first stroke's start replaces the way from home.
  const auto first_stroke = std::find_if(one.begin(), one.end(),
                                         [](const Command& c) { return c.role == CommandRole::stroke; });
  const auto last_stroke = std::find_if(one.rbegin(), one.rend(),
                                        [](const Command& c) { return c.role == CommandRole::stroke; });
  double again_mm = plan.jump_length_mm;
  if (first_stroke != one.end())
    again_mm += (first_stroke->start() - last_stroke->end()).norm() -
                (first_stroke->start() - plan.home).norm();

  plan.commands.reserve(one.size() * static_cast<std::size_t>(passes) + static_cast<std::size_t>(passes));
  for (int p = 1; p < passes; ++p) {
    const Point at = plan.commands.back().end();
    if ((entry - at).norm() > kJoinTolerance_mm)
      plan.commands.push_back(Command::jump(at, entry, plan.pen.jump_speed_mm_s));
    plan.commands.insert(plan.commands.end(), first_mark, one.end());
  }
  plan.strokes *= static_cast<std::size_t>(passes);
  plan.jump_length_mm += (passes - 1) * again_mm;
}

}  // namespace mark

#pragma once
// The three dot-peen planners behind one call, with the marking window they share.
#include <optional>
#include <string_view>

#include "marker/peen/dot_text.hpp"
#include "marker/peen/gantry.hpp"
#include "marker/peen/peen_plan.hpp"
#include "base/progress.hpp"

namespace mark {

enum class PlannerKind { snake, block, optimized };

inline constexpr PlannerKind kAllPlanners[] = {PlannerKind::snake, PlannerKind::block,
                                               PlannerKind::optimized};

const char* planner_name(PlannerKind kind);
// "snake", "block" or "optimized"; nullopt otherwise.
std::optional<PlannerKind> parse_planner(std::string_view name);

// The marking window: the area the gantry sweeps (the whole-window snake covers all of it) and
// whose top-left corner is home for every planner.
struct PeenSetup {
  Box window;
  GantryConfig gantry;
  bool block_one_axis_at_a_time = true;  // see plan_block_snake
  const Progress* progress = &Progress::none();  // the optimiser reports to it; may stop it (Interrupted)
};

// The dots' bounding box: the smallest window, the most favourable to the whole-window snake.
Box tight_window(const DotText& text);
// A window of width × height mm centred on the field origin (where the layout centres the field).
Box centred_window(double width_mm, double height_mm);
Point home_of(const Box& window);

// Throws InputError when the text has no dots, or naming how far the dots leave the window.
void require_in_window(const DotText& text, const Box& window);

PeenPlan plan_peen(const DotText& text, PlannerKind kind, const PeenSetup& setup);

}  // namespace mark

#pragma once
// The classic whole-window snake (the baseline the dot-peen patent replaced): the head sweeps the
// whole marking window row by row at the dot pitch, left to right, one row down, right to left,
// striking each dot as it passes, and turns at the window's edges whether or not the row has dots.
#include "marker/peen/dot_text.hpp"
#include "marker/peen/peen_plan.hpp"

namespace mark {

// Home is the window's top-left corner. Rows lie every text.pitch_mm on the dots' own row grid,
// from the highest one inside the window down to the lowest; each dot belongs to the nearest row
// and every row is swept from one side edge of the window to the other. Dots must lie in the
// window.
PeenPlan plan_window_snake(const DotText& text, const Box& window);

}  // namespace mark

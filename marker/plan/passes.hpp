#pragma once
// A pen's passes: the same strokes marked again on top (deeper, darker marks). After the last
// command of a pass the mirrors jump, laser off, to where the pass began marking — where its
// first jump from home landed — and the pass's commands run again. Counts (strokes, jump
// length) cover every pass.
#include "marker/plan/plan.hpp"

namespace mark {

// passes ≥ 1; 1 leaves the plan as it is.
void repeat_passes(Plan& plan, int passes);

}  // namespace mark

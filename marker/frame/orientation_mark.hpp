#pragma once
// The orientation mark `marker frame` traces with the red pointer before anything fires: a
// small "F" beside the job, at its +x side, upright in the field frame (x right, y up). An F is
// chiral — no rotation or mirror maps it onto itself — so the operator sees at a glance whether
// the head's axes are wired as the driver assumes (--swap-xy, --flip-x, --flip-y): on the part
// it must read as an F, to the right of the text.
#include <vector>

#include "driver/vec2.hpp"
#include "fonts/box.hpp"

namespace mark {

// One polyline tracing an F of height `h` with its lower-left corner at (x, y): up the stem,
// along the top bar and back, down to the middle bar and along it.
std::vector<Vec2> letter_f(double x, double y, double h);

// The F beside `job` (its bounds, mm): as tall as the job but 2 to 10 mm, half its height to
// the right of it, centred on it; on the left where the right side leaves the field, inside
// the box where neither side has room. Throws InputError for an empty box.
std::vector<Vec2> orientation_mark(const Box& job, double field_mm);

}  // namespace mark

#pragma once
// Stroke order: keep the glyph order (what the font designer drew), or minimise the jump length
// (nearest neighbour with reversal of strokes, then 2-opt). Either way the total jump length is
// reported, measured from the home position through every stroke.
#include <string_view>
#include <vector>

#include "marker/plan/stroke.hpp"

namespace mark {

enum class StrokeOrder { glyph, shortest };

std::string_view to_string(StrokeOrder order);
// "glyph" or "shortest"; throws InputError naming the value otherwise.
StrokeOrder parse_stroke_order(std::string_view name);

// Sum of the straight distances home → first start, each end → next start, mm.
double jump_length_mm(const std::vector<Stroke>& strokes, const Point& home);

// Reorders (and, for `shortest`, may reverse) the strokes. Every stroke appears exactly once.
std::vector<Stroke> order_strokes(std::vector<Stroke> strokes, StrokeOrder order,
                                  const Point& home);

}  // namespace mark

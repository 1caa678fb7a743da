#pragma once
// Preview of a needle path as SVG or PNG (by the file's extension): the marking window, the dots
// (filled discs, a pitch apart), the head's route from home through every stop and back (thin
// line; turn points as small squares), and home (a ring).
#include <string>

#include "marker/peen/dot_text.hpp"
#include "marker/peen/peen_plan.hpp"

namespace mark {

// Throws InputError naming the file if it cannot be written or its extension is not .svg/.png.
void write_peen_preview(const DotText& text, const PeenPlan& plan, const Box& window,
                        const std::string& path);

}  // namespace mark

#pragma once
// Depression (engraved) letters, as in the paper's depression font generator: the tool centre
// follows each stroke at depth, in passes of at most the depth per pass. One subprogram per
// distinct character cuts all of its strokes in its own coordinates; the main program calls it
// at every occurrence with the occurrence's origin and rotation.
#include "marker/cnc/cut_settings.hpp"
#include "marker/cnc/toolpath.hpp"
#include "marker/layout/figure.hpp"

namespace mark {

// Throws InputError for impossible settings and for a text without strokes (only spaces).
Toolpath depression_toolpath(const Figure& figure, const CutSettings& settings);

}  // namespace mark

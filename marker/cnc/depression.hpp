#pragma once
// Depression (engraved) letters, as in the paper's depression font generator: the tool centre
// follows each stroke at depth, in passes of at most the depth per pass.
//
// The strokes of the whole text are ordered together (marker/order: a letter's strokes may be
// interleaved with its neighbours' where that saves rapid travel, as F-Engrave orders all
// strokes of a job together), so the subprograms are per stroke: one per distinct character,
// stroke and direction used, in the character's own coordinates, called at each occurrence with
// the occurrence's origin and rotation.
#include "base/progress.hpp"
#include "marker/cnc/cut_settings.hpp"
#include "marker/cnc/toolpath.hpp"
#include "marker/layout/figure.hpp"

namespace mark {

// Throws InputError for impossible settings and for a text without strokes (only spaces);
// Interrupted when `progress` says stop.
Toolpath depression_toolpath(const Figure& figure, const CutSettings& settings,
                             const Progress& progress = Progress::none());

}  // namespace mark

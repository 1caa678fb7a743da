#pragma once
// What a hatch fill accepts (a filled text, a code's modules), wherever it is given: the
// --hatch-… and --contour-… options, a job file's "fill" and "hatch", the fill library's checks.
#include "marker/limits/value_range.hpp"

namespace mark {

inline const Range kHatchSpacingRange = length_range(0.001, 10);
inline const Range kHatchAngleRange{-360, 360, "degrees"};
inline const WholeRange kHatchSetsRange{1, 8};
// Insets: a few beam radii; more than 5 mm leaves nothing of any letter.
inline const Range kFillInsetRange = length_range(0, 5);
inline const WholeRange kContourPassesRange{0, 100};
inline const Range kMinHatchLineRange = length_range(0, 1);
inline const Range kFillChordRange = length_range(1e-5, 0.01);

}  // namespace mark

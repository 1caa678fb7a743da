#pragma once
// Head identification, the fitting half (driver/sim/head_response.hpp measures): from the command
// pattern and the recorded mirror positions alone, fit
//
//   - a first-order servo ẋ = (c − x)/τ and a second-order one ẍ = ωn²(c − x) − 2ζωn·ẋ, by least
//     squares over the linear parts of the test (small steps, ramps, chirp), each part simulated
//     exactly from the recorded state before it with the command held first-order between
//     ticks as the head sees it;
//   - the speed limit, the highest speed reached in the large steps (they cruise there);
//   - the acceleration limit, the slope of the speed while the largest steps speed up (a
//     straight line while the servo is saturated).
//
// The model with the clearly smaller residual becomes the profile's model; a second-order fit
// whose ζ runs off to heavy damping (≥ 3: a first-order head with a sub-tick delay) does not.
#include <string>

#include "driver/sim/head_response.hpp"
#include "marker/head/head_profile.hpp"

namespace mark {

// Throws InputError if the record holds no usable linear or large-step part (a head that did
// not move).
HeadProfile fit_head_profile(const ResponseRecord& record, const std::string& head_name,
                             double field_mm);

// Both halves for the simulated head: the pattern for its field, measured and fitted.
HeadProfile identify_head(const SimScannerOptions& head);

}  // namespace mark

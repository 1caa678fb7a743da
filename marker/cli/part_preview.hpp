#pragma once
// The next part's picture (`marker job check FILE --preview OUT` and the station's
// GET /api/preview.png): one function, so both show the same bytes for the same state.
#include <string>
#include <vector>

#include "marker/production/part_texts.hpp"

namespace mark::cli {

// Every object of the part with these texts simulated (marker/production/part_picture.hpp:
// simulate_part, nothing consumed) and drawn as `marker mark --preview` draws a mark, encoded
// as `format`'s extension says (.png or .svg).
std::string next_part_preview(const JobFile& job, const JobFonts& fonts, const std::vector<ObjectText>& texts,
                              const std::string& format);

}  // namespace mark::cli

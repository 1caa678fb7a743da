#pragma once
// Parsing the structured values of `marker gravure`: the screen ("70" or "70x60" lines/cm), head
// resonances ("1800:0.06:0.8,5500:0.04:0.2"), notch filters ("1800:0.06:18") and the emphasis
// filter ("5500:0.5:20000:0.707"). Every value is range-checked; errors name the option, the
// value and the allowed range in one line.
#include <string>

#include "driver/sim/stylus_head_model.hpp"
#include "marker/gravure/screen.hpp"
#include "marker/gravure/tuning_filter.hpp"

namespace mark::cli {

// Sets cells_per_mm_along / _across from lines per centimetre.
void parse_screen(const std::string& option, const std::string& text, GravureScreen& screen);
StylusHeadModel parse_head(const std::string& option, const std::string& text);
FilterSection parse_notch(const std::string& option, const std::string& text);
FilterSection parse_emphasis(const std::string& option, const std::string& text);

}  // namespace mark::cli

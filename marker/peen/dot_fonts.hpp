#pragma once
// The built-in dot-matrix fonts at the common industrial grids. Each covers the digits, the
// upper-case letters and the punctuation serial numbers and VINs use; 5x7 and 7x9 also carry
// '-', '.', '/', ':', '#', '+', '?' and the space.
#include <string_view>
#include <vector>

#include "marker/peen/dot_font.hpp"

namespace mark {

const DotFont& dot_font_5x7();
const DotFont& dot_font_7x9();
// A 10x16 grid like the one in the dot-peen patent's timing example (its "8").
const DotFont& dot_font_10x16();

// "5x7", "7x9" or "10x16"; nullptr for any other name.
const DotFont* find_dot_font(std::string_view name);
std::vector<std::string_view> dot_font_names();

}  // namespace mark

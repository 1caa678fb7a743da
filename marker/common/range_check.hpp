#pragma once
// One rule for every numeric parameter a user can give: a value outside its range (or not a
// number at all) is refused with one line naming the parameter, the value and the range —
// never clipped silently.
#include <string_view>

namespace mark {

// Throws InputError "WHAT VALUE UNIT is outside LO .. HI UNIT" unless lo ≤ value ≤ hi (and
// finite). `unit` may be empty.
void require_in_range(std::string_view what, double value, double lo, double hi,
                      std::string_view unit = "");

}  // namespace mark

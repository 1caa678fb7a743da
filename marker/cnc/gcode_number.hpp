#pragma once
// Numbers as G-code words: fixed decimals, trailing zeros dropped, the decimal point always
// written ("10." not "10") because Fanuc-type controls read a number without a point in
// least-input increments (X10 = 0.010 mm); never "-0.".
#include <string>

namespace mark {

// Appends v with at most `decimals` decimals.
void append_number(std::string& out, double v, int decimals);
std::string format_number(double v, int decimals);
// v rounded to `decimals` decimals, as the controller will read it back.
double round_to(double v, int decimals);

}  // namespace mark

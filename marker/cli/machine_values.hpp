#pragma once
// The values of a milling machine's envelope on the command line: --stock "W,H" (lower-left
// corner at the work origin) or "X,Y,W,H" (lower-left corner at X,Y), and --travel "X,Y", all in
// millimetres. Read with the one number parser (option_values.hpp) and checked against
// marker/limits/cnc_limits.hpp; fuzzed with the other option values (tests/fuzz).
#include <string>
#include <utility>

#include "fonts/box.hpp"

namespace mark::cli {

// Throws InputError naming --stock, the text and what is wrong (count, a part that is not a
// number, a size or corner outside its range).
Box parse_stock(const std::string& text);

// {x, y} in mm; throws InputError naming --travel likewise.
std::pair<double, double> parse_travel(const std::string& text);

}  // namespace mark::cli

#include "marker/cnc/gcode_number.hpp"

#include <charconv>
#include <cmath>

namespace mark {

double round_to(double v, int decimals) {
  const double scale = std::pow(10.0, decimals);
  return std::round(v * scale) / scale;
}

void append_number(std::string& out, double v, int decimals) {
  char buf[64];
  v = round_to(v, decimals);
  if (v == 0) v = 0;  // −0 → 0
  auto [end, ec] = std::to_chars(buf, buf + sizeof buf, v, std::chars_format::fixed, decimals);
  if (ec != std::errc()) {  // only for absurd magnitudes, which validation keeps out
    out += "0.";
    return;
  }
  char* p = end;
  if (decimals > 0) {
    while (p[-1] == '0') --p;
  } else {
    *p++ = '.';
  }
  out.append(buf, p);
}

std::string format_number(double v, int decimals) {
  std::string s;
  append_number(s, v, decimals);
  return s;
}

}  // namespace mark

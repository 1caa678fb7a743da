#include "marker/cli/machine_values.hpp"

#include <algorithm>
#include <vector>

#include "marker/cli/option_values.hpp"
#include "marker/limits/cnc_limits.hpp"
#include "marker/limits/layout_settings.hpp"

namespace mark::cli {

Box parse_stock(const std::string& text) {
  const std::size_t commas = static_cast<std::size_t>(std::count(text.begin(), text.end(), ','));
  const std::vector<double> v = parse_numbers("--stock", text, ",", commas == 3 ? 4 : 2,
                                              "W,H or X,Y,W,H in millimetres (lower-left corner at 0,0 or at X,Y)");
  const std::string option = "--stock '" + text + "'";
  const double x = v.size() == 4 ? v[0] : 0, y = v.size() == 4 ? v[1] : 0;
  const double w = v[v.size() - 2], h = v[v.size() - 1];
  if (v.size() == 4) {
    check_range(option + " corner x", x, kPositionBounds.range());
    check_range(option + " corner y", y, kPositionBounds.range());
  }
  check_range(option + " width", w, kStockSizeRange);
  check_range(option + " height", h, kStockSizeRange);
  Box b;
  b.add(Point(x, y));
  b.add(Point(x + w, y + h));
  return b;
}

std::pair<double, double> parse_travel(const std::string& text) {
  const std::vector<double> v = parse_numbers("--travel", text, ",", 2, "X,Y in millimetres");
  check_range("--travel '" + text + "' x", v[0], kTravelRange);
  check_range("--travel '" + text + "' y", v[1], kTravelRange);
  return {v[0], v[1]};
}

}  // namespace mark::cli

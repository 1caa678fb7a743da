#include "marker/common/range_check.hpp"

#include <cmath>
#include <sstream>

#include "fonts/error.hpp"

namespace mark {

void require_in_range(std::string_view what, double value, double lo, double hi,
                      std::string_view unit) {
  if (std::isfinite(value) && value >= lo && value <= hi) return;
  std::ostringstream s;
  s << what << " " << value;
  if (!unit.empty()) s << " " << unit;
  s << " is outside " << lo << " .. " << hi;
  if (!unit.empty()) s << " " << unit;
  throw InputError(s.str());
}

}  // namespace mark

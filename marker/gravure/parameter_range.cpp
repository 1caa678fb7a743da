#include "marker/gravure/parameter_range.hpp"

#include <cmath>
#include <cstdio>

#include "fonts/error.hpp"

namespace mark {

void check_range(const std::string& name, double value, const ParameterRange& r) {
  if (std::isfinite(value) && value >= r.lo && value <= r.hi) return;
  char buf[160];
  std::snprintf(buf, sizeof buf, " %g: outside %g .. %g%s%s", value, r.lo, r.hi, *r.unit ? " " : "", r.unit);
  throw InputError(name + buf);
}

}  // namespace mark

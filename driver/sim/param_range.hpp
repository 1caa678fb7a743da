#pragma once
// The simulator's own check of a model parameter (camera, part look, material response): a value
// outside its range, or not finite, throws std::invalid_argument naming the model, the
// parameter, the value and the range. The command line checks the same values against
// marker/limits first with its own wording; this is the backstop for every other caller.
#include <cmath>
#include <sstream>
#include <stdexcept>
#include <string_view>

namespace mark {

inline void require_param_range(std::string_view model, std::string_view what, double v, double lo, double hi,
                                std::string_view unit = {}) {
  if (std::isfinite(v) && v >= lo && v <= hi) return;
  std::ostringstream s;
  if (!model.empty()) s << model << ": ";
  s << what << " " << v;
  if (!unit.empty()) s << " " << unit;
  s << " is outside " << lo << " .. " << hi;
  if (!unit.empty()) s << " " << unit;
  throw std::invalid_argument(s.str());
}

}  // namespace mark

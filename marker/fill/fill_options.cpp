#include "marker/fill/fill_options.hpp"

#include <cmath>
#include <string>

#include "fonts/error.hpp"
#include "marker/common/range_check.hpp"

namespace mark {
namespace {

[[noreturn]] void unknown(std::string_view what, std::string_view name, std::string_view allowed) {
  throw InputError(std::string(what) + " '" + std::string(name) + "' is not one of " +
                   std::string(allowed));
}

}  // namespace

std::string_view to_string(FillRule r) { return r == FillRule::non_zero ? "nonzero" : "evenodd"; }
std::string_view to_string(HatchDirection d) {
  return d == HatchDirection::bidirectional ? "bidirectional" : "unidirectional";
}
std::string_view to_string(HatchOrder o) { return o == HatchOrder::short_jumps ? "short" : "raster"; }
std::string_view to_string(ContourPlacement p) {
  return p == ContourPlacement::before ? "before" : "after";
}

FillRule parse_fill_rule(std::string_view name) {
  if (name == "nonzero") return FillRule::non_zero;
  if (name == "evenodd") return FillRule::even_odd;
  unknown("fill rule", name, "nonzero, evenodd");
}

HatchDirection parse_hatch_direction(std::string_view name) {
  if (name == "bidirectional" || name == "bi") return HatchDirection::bidirectional;
  if (name == "unidirectional" || name == "uni") return HatchDirection::unidirectional;
  unknown("hatch direction", name, "bidirectional, unidirectional");
}

HatchOrder parse_hatch_order(std::string_view name) {
  if (name == "short") return HatchOrder::short_jumps;
  if (name == "raster") return HatchOrder::raster;
  unknown("hatch order", name, "short, raster");
}

ContourPlacement parse_contour_placement(std::string_view name) {
  if (name == "before") return ContourPlacement::before;
  if (name == "after") return ContourPlacement::after;
  unknown("contour placement", name, "before, after");
}

void check_fill_options(const FillOptions& o) {
  if (o.sets.empty() && o.contour_passes == 0)
    throw InputError("fill: no hatch set and no contour pass: nothing would be marked");
  if (o.sets.size() > 8)
    throw InputError("fill: " + std::to_string(o.sets.size()) + " hatch sets, at most 8");
  for (const HatchSet& s : o.sets) {
    require_in_range("hatch spacing", s.spacing_mm, 0.001, 10, "mm");
    require_in_range("hatch angle", s.angle_deg, -360, 360, "deg");
  }
  require_in_range("hatch inset", o.inset_mm, 0, 5, "mm");
  require_in_range("contour passes", o.contour_passes, 0, 100, "");
  require_in_range("contour inset", o.contour_inset_mm, 0, 5, "mm");
  require_in_range("contour spacing", o.contour_spacing_mm, 0.001, 10, "mm");
  require_in_range("minimum hatch line", o.min_line_mm, 0, 1, "mm");
  require_in_range("fill chord tolerance", o.chord_tolerance_mm, 1e-5, 0.01, "mm");
  if (!std::isfinite(o.origin.x()) || !std::isfinite(o.origin.y()))
    throw InputError("hatch origin is not a finite point");
}

}  // namespace mark

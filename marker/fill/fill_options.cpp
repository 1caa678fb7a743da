#include "marker/fill/fill_options.hpp"

#include <cmath>
#include <string>

#include "base/error.hpp"
#include "marker/limits/fill_settings.hpp"

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
  if (!kHatchSetsRange.contains(static_cast<std::int64_t>(o.sets.size())))
    throw InputError("fill: " + std::to_string(o.sets.size()) + " hatch sets, at most " +
                     std::to_string(kHatchSetsRange.max));
  for (const HatchSet& s : o.sets) {
    check_range("hatch spacing", s.spacing_mm, kHatchSpacing.range());
    check_range("hatch angle", s.angle_deg, kHatchAngle.range());
  }
  check_range("hatch inset", o.inset_mm, kHatchInset.range());
  if (!kContourPasses.range.contains(o.contour_passes))
    throw InputError("contour passes: " + std::to_string(o.contour_passes) + " is outside the range " +
                     kContourPasses.range.text());
  check_range("contour inset", o.contour_inset_mm, kContourInset.range());
  check_range("contour spacing", o.contour_spacing_mm, kContourSpacing.range());
  check_range("minimum hatch line", o.min_line_mm, kMinHatchLineBounds.range());
  check_range("fill chord tolerance", o.chord_tolerance_mm, kFillChordBounds.range());
  if (!std::isfinite(o.origin.x()) || !std::isfinite(o.origin.y()))
    throw InputError("hatch origin is not a finite point");
}

}  // namespace mark

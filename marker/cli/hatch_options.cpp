#include "marker/cli/hatch_options.hpp"

#include <algorithm>

#include "base/error.hpp"
#include "marker/cli/option_ranges.hpp"
#include "marker/limits/fill_limits.hpp"

namespace mark::cli {

void add_hatch_options(CLI::App& app, HatchArgs& a) {
  add_ranged_option(app, "--hatch-spacing", a.spacing_mm,
                    "distance between hatch lines, mm; a list gives one per hatch set (default 0.035)",
                    kHatchSpacingRange);
  add_ranged_option(app, "--hatch-angle", a.angle_deg,
                    "hatch direction, degrees; a list gives several hatch sets, e.g. 0,90 (default 0)",
                    kHatchAngleRange);
  app.add_option("--hatch-direction", a.direction, "bidirectional (serpentine) or unidirectional")->capture_default_str();
  app.add_option("--hatch-order", a.order, "short (blocks ordered to keep jumps short) or raster (scanline order)")
      ->capture_default_str();
  add_ranged_option(app, "--hatch-inset", a.inset_mm,
                    "hatch lines end this far inside the outline, mm (default: the beam radius)", kFillInsetRange);
  add_ranged_option(app, "--contour-passes", a.contour_passes, "loops along the outline (0: hatch only)",
                    kContourPassesRange)->capture_default_str();
  app.add_option("--contour-placement", a.contour_placement, "contour passes before or after the hatch")->capture_default_str();
  add_ranged_option(app, "--contour-inset", a.contour_inset_mm,
                    "first contour loop inside the outline, mm (default: the beam radius)", kFillInsetRange);
  add_ranged_option(app, "--contour-spacing", a.contour_spacing_mm,
                    "between contour loops, mm (default: the hatch spacing)", kHatchSpacingRange);
}

FillOptions to_fill_options(const HatchArgs& a, double beam_radius_mm) {
  FillOptions o;
  const std::size_t sets = std::max<std::size_t>({1, a.spacing_mm.size(), a.angle_deg.size()});
  for (const auto* list : {&a.spacing_mm, &a.angle_deg})
    if (list->size() > 1 && list->size() != sets)
      throw InputError("--hatch-spacing and --hatch-angle give " + std::to_string(a.spacing_mm.size()) +
                       " and " + std::to_string(a.angle_deg.size()) +
                       " values: give one, or one per hatch set");
  if (!kHatchSetsRange.contains(static_cast<std::int64_t>(sets)))
    throw InputError("--hatch-spacing / --hatch-angle: " + std::to_string(sets) + " hatch sets, at most " +
                     std::to_string(kHatchSetsRange.max));
  o.sets.clear();
  for (std::size_t k = 0; k < sets; ++k) {
    HatchSet s;
    if (!a.spacing_mm.empty()) s.spacing_mm = a.spacing_mm[a.spacing_mm.size() == 1 ? 0 : k];
    if (!a.angle_deg.empty()) s.angle_deg = a.angle_deg[a.angle_deg.size() == 1 ? 0 : k];
    o.sets.push_back(s);
  }
  o.direction = parse_hatch_direction(a.direction);
  o.order = parse_hatch_order(a.order);
  o.inset_mm = a.inset_mm.value_or(beam_radius_mm);
  o.contour_passes = a.contour_passes;
  o.contour_placement = parse_contour_placement(a.contour_placement);
  o.contour_inset_mm = a.contour_inset_mm.value_or(beam_radius_mm);
  o.contour_spacing_mm = a.contour_spacing_mm.value_or(o.sets.front().spacing_mm);
  check_fill_options(o);
  return o;
}

}  // namespace mark::cli

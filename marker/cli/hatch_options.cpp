#include "marker/cli/hatch_options.hpp"

#include <algorithm>

#include "base/error.hpp"
#include "marker/cli/option_ranges.hpp"
#include "marker/limits/fill_settings.hpp"

namespace mark::cli {

void add_hatch_options(CLI::App& app, HatchArgs& a) {
  add_setting(app, kHatchSpacing, a.spacing_mm);
  add_setting(app, kHatchAngle, a.angle_deg);
  add_setting(app, kHatchDirection, a.direction);
  add_setting(app, kHatchOrder, a.order);
  add_setting(app, kHatchInset, a.inset_mm);
  add_setting(app, kContourPasses, a.contour_passes);
  add_setting(app, kContourPlacement, a.contour_placement);
  add_setting(app, kContourInset, a.contour_inset_mm);
  add_setting(app, kContourSpacing, a.contour_spacing_mm);
}

FillOptions to_fill_options(const HatchArgs& a, double beam_radius_mm) {
  FillOptions o;
  const std::size_t sets = std::max<std::size_t>({1, a.spacing_mm.size(), a.angle_deg.size()});
  for (const auto* list : {&a.spacing_mm, &a.angle_deg})
    if (list->size() > 1 && list->size() != sets)
      throw InputError(std::string(kHatchSpacing.name.flag) + " and " + std::string(kHatchAngle.name.flag) + " give " +
                     std::to_string(a.spacing_mm.size()) +
                       " and " + std::to_string(a.angle_deg.size()) +
                       " values: give one, or one per hatch set");
  if (!kHatchSetsRange.contains(static_cast<std::int64_t>(sets)))
    throw InputError(std::string(kHatchSpacing.name.flag) + " / " + std::string(kHatchAngle.name.flag) + ": " +
                     std::to_string(sets) + " hatch sets, at most " + std::to_string(kHatchSetsRange.max));
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

#include "marker/fill/contour_passes.hpp"

#include <algorithm>
#include <limits>

#include "marker/fill/arc_refit.hpp"
#include "marker/geometry/clipper_paths.hpp"

namespace mark {
namespace {

// The loop turned so it starts at its element start nearest to p.
std::vector<Element> entered_near(std::vector<Element> loop, const Point& p) {
  std::size_t best = 0;
  double best_d = std::numeric_limits<double>::infinity();
  for (std::size_t k = 0; k < loop.size(); ++k) {
    const double d = (loop[k].start() - p).squaredNorm();
    if (d < best_d) best_d = d, best = k;
  }
  std::rotate(loop.begin(), loop.begin() + static_cast<std::ptrdiff_t>(best), loop.end());
  return loop;
}

}  // namespace

std::vector<std::vector<Element>> contour_loops(const FillRegion& region, const FillOptions& o,
                                                Point& at) {
  std::vector<std::vector<Element>> loops;
  // A vertex of an offset is off the exact offset curve by the flattening of the outline and of
  // the round joins, each within the chord tolerance; Clipper's nanometre grid adds a little.
  const double tolerance = 2 * o.chord_tolerance_mm + 2e-6;
  for (int pass = 0; pass < o.contour_passes; ++pass) {
    const double inset = o.contour_inset_mm + pass * o.contour_spacing_mm;
    const ClipperLib::Paths polys = region.inset(inset);
    if (polys.empty()) break;
    for (const ClipperLib::Path& poly : polys) {
      std::vector<Element> loop = refit_loop(to_mm(poly), region.sources, {inset, tolerance});
      if (!loop.empty()) loops.push_back(std::move(loop));
    }
  }
  // Nearest loop first, each entered where the beam is closest.
  std::vector<std::vector<Element>> ordered;
  std::vector<bool> used(loops.size(), false);
  for (std::size_t n = 0; n < loops.size(); ++n) {
    std::size_t pick = 0;
    double best = std::numeric_limits<double>::infinity();
    for (std::size_t k = 0; k < loops.size(); ++k) {
      if (used[k]) continue;
      for (const Element& e : loops[k]) {
        const double d = (e.start() - at).squaredNorm();
        if (d < best) best = d, pick = k;
      }
    }
    used[pick] = true;
    ordered.push_back(entered_near(std::move(loops[pick]), at));
    at = ordered.back().back().end();
  }
  return ordered;
}

}  // namespace mark

#include "fonts/stroke_join.hpp"

#include <utility>

namespace mark {
namespace {

// A lit line no longer than the tolerance: a point (a dot to strike or drill), not a direction.
bool is_point(const Element& e, double tol) {
  return e.kind() == ElementKind::line && ends_meet(e.start(), e.end(), tol);
}
bool is_point(const ChainedStroke& s, double tol) { return s.elements.size() == 1 && is_point(s.elements.front(), tol); }

}  // namespace

ChainedStroke ChainedStroke::reversed() const {
  ChainedStroke r;
  r.elements.reserve(elements.size());
  for (auto it = elements.rbegin(); it != elements.rend(); ++it) r.elements.push_back(it->reversed());
  return r;
}

std::vector<ChainedStroke> chain_strokes(const std::vector<Element>& elements, double tol) {
  std::vector<ChainedStroke> runs;
  bool open = false;
  for (const Element& e : elements) {
    if (!e.laser()) {
      open = false;
      continue;
    }
    const bool point = is_point(e, tol);
    if (open && ends_meet(runs.back().end(), e.start(), tol)) {
      if (point) continue;  // a repeated point has no direction
      if (is_point(runs.back(), tol))
        runs.back().elements.front() = e;  // the run's lone point is where e starts
      else
        runs.back().elements.push_back(e);
    } else {
      runs.push_back(ChainedStroke{{e}});
    }
    open = true;
  }
  // Join runs end to end (either may be reversed) until no two open runs share an end. A glyph
  // has a handful of runs, so the quadratic search costs nothing.
  bool joined = true;
  while (joined) {
    joined = false;
    for (std::size_t i = 0; i < runs.size() && !joined; ++i) {
      if (runs[i].closed(tol)) continue;
      for (std::size_t j = i + 1; j < runs.size() && !joined; ++j) {
        if (runs[j].closed(tol)) continue;
        ChainedStroke a = runs[i], b = runs[j];
        if (ends_meet(a.end(), b.start(), tol)) {
        } else if (ends_meet(a.end(), b.end(), tol)) {
          b = b.reversed();
        } else if (ends_meet(a.start(), b.end(), tol)) {
          std::swap(a, b);
        } else if (ends_meet(a.start(), b.start(), tol)) {
          a = a.reversed();
        } else {
          continue;
        }
        a.elements.insert(a.elements.end(), b.elements.begin(), b.elements.end());
        runs[i] = std::move(a);
        runs.erase(runs.begin() + static_cast<std::ptrdiff_t>(j));
        joined = true;
      }
    }
  }
  // A lone point where a stroke passes adds nothing: the stroke marks it.
  std::vector<bool> covered(runs.size(), false);
  for (std::size_t i = 0; i < runs.size(); ++i) {
    if (!is_point(runs[i], tol)) continue;
    for (std::size_t j = 0; j < runs.size() && !covered[i]; ++j)
      covered[i] = j != i && (j < i || !is_point(runs[j], tol)) &&
                   (ends_meet(runs[i].start(), runs[j].start(), tol) || ends_meet(runs[i].start(), runs[j].end(), tol));
  }
  std::vector<ChainedStroke> out;
  out.reserve(runs.size());
  for (std::size_t i = 0; i < runs.size(); ++i)
    if (!covered[i]) out.push_back(std::move(runs[i]));
  return out;
}

}  // namespace mark

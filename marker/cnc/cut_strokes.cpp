#include "marker/cnc/cut_strokes.hpp"

#include <algorithm>

namespace mark {

CutStroke CutStroke::reversed() const {
  CutStroke r;
  r.elements.reserve(elements.size());
  for (auto it = elements.rbegin(); it != elements.rend(); ++it) r.elements.push_back(it->reversed());
  return r;
}

std::vector<CutStroke> chain_cut_strokes(const std::vector<Element>& elements, double tol) {
  std::vector<CutStroke> runs;
  bool open = false;
  for (const Element& e : elements) {
    if (!e.laser()) {
      open = false;
      continue;
    }
    if (open && (runs.back().end() - e.start()).norm() <= tol)
      runs.back().elements.push_back(e);
    else
      runs.push_back(CutStroke{{e}});
    open = true;
  }
  // Join runs end to end (either may be reversed) until no two open runs share an endpoint.
  bool joined = true;
  while (joined) {
    joined = false;
    for (std::size_t i = 0; i < runs.size() && !joined; ++i) {
      if (runs[i].closed(tol)) continue;
      for (std::size_t j = i + 1; j < runs.size() && !joined; ++j) {
        if (runs[j].closed(tol)) continue;
        CutStroke a = runs[i], b = runs[j];
        if ((a.end() - b.start()).norm() <= tol) {
        } else if ((a.end() - b.end()).norm() <= tol) {
          b = b.reversed();
        } else if ((a.start() - b.end()).norm() <= tol) {
          std::swap(a, b);
        } else if ((a.start() - b.start()).norm() <= tol) {
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
  return runs;
}

}  // namespace mark

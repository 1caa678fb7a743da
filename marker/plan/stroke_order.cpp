// Jump-length minimisation: an open path through the strokes (start at home, no return), each
// stroke entered at either end. Nearest neighbour builds a tour; 2-opt then reverses sub-sequences
// (reversing each stroke inside them too, so the segment's inner jumps keep their lengths) while
// that shortens the path.
#include "marker/plan/stroke_order.hpp"

#include <algorithm>
#include <limits>
#include <string>

#include "fonts/error.hpp"

namespace mark {
namespace {

// Passes of 2-opt over the whole sequence; each pass is O(n²). The bound only matters for very
// large jobs, where 2-opt gains little after a few passes anyway.
constexpr int kMaxTwoOptPasses = 50;

double dist(const Point& a, const Point& b) { return (a - b).norm(); }

std::vector<Stroke> nearest_neighbour(std::vector<Stroke> pool, const Point& home) {
  std::vector<Stroke> tour;
  tour.reserve(pool.size());
  Point at = home;
  while (!pool.empty()) {
    std::size_t best = 0;
    bool flip = false;
    double best_d = std::numeric_limits<double>::infinity();
    for (std::size_t i = 0; i < pool.size(); ++i) {
      const double ds = dist(at, pool[i].start());
      if (ds < best_d) best_d = ds, best = i, flip = false;
      const double de = dist(at, pool[i].end());
      if (de < best_d) best_d = de, best = i, flip = true;
    }
    Stroke s = flip ? pool[best].reversed() : std::move(pool[best]);
    pool[best] = std::move(pool.back());
    pool.pop_back();
    at = s.end();
    tour.push_back(std::move(s));
  }
  return tour;
}

// Reverse strokes [a, b] of the tour (order and direction) when that shortens the path. The
// predecessor of stroke 0 is home; the last stroke has no successor.
void two_opt(std::vector<Stroke>& tour, const Point& home) {
  const std::size_t n = tour.size();
  std::vector<Point> s(n), e(n);
  auto refresh = [&] {
    for (std::size_t i = 0; i < n; ++i) s[i] = tour[i].start(), e[i] = tour[i].end();
  };
  refresh();
  for (int pass = 0; pass < kMaxTwoOptPasses; ++pass) {
    bool improved = false;
    for (std::size_t a = 0; a < n; ++a) {
      const Point prev = a == 0 ? home : e[a - 1];
      for (std::size_t b = a; b < n; ++b) {
        const double before = dist(prev, s[a]) + (b + 1 < n ? dist(e[b], s[b + 1]) : 0.0);
        const double after = dist(prev, e[b]) + (b + 1 < n ? dist(s[a], s[b + 1]) : 0.0);
        if (after < before - 1e-9) {
          std::reverse(tour.begin() + a, tour.begin() + b + 1);
          for (std::size_t i = a; i <= b; ++i) tour[i] = tour[i].reversed();
          refresh();
          improved = true;
        }
      }
    }
    if (!improved) break;
  }
}

}  // namespace

std::string_view to_string(StrokeOrder order) {
  return order == StrokeOrder::glyph ? "glyph" : "shortest";
}

StrokeOrder parse_stroke_order(std::string_view name) {
  if (name == "glyph") return StrokeOrder::glyph;
  if (name == "shortest") return StrokeOrder::shortest;
  throw InputError("stroke order '" + std::string(name) + "' is not one of glyph, shortest");
}

double jump_length_mm(const std::vector<Stroke>& strokes, const Point& home) {
  double len = 0;
  Point at = home;
  for (const Stroke& s : strokes) {
    len += dist(at, s.start());
    at = s.end();
  }
  return len;
}

std::vector<Stroke> order_strokes(std::vector<Stroke> strokes, StrokeOrder order,
                                  const Point& home) {
  if (order == StrokeOrder::glyph || strokes.size() < 2) return strokes;
  std::vector<Stroke> tour = nearest_neighbour(std::move(strokes), home);
  two_opt(tour, home);
  return tour;
}

}  // namespace mark

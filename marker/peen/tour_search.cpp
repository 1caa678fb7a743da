#include "marker/peen/tour_search.hpp"

#include <algorithm>
#include <deque>

#include "marker/peen/point_grid.hpp"

namespace mark {
namespace {

// Smallest gain (seconds) worth a move: keeps rounding noise from cycling the search.
constexpr double kMinGain = 1e-12;

// A cyclic tour as an array of points plus each point's position in it.
class Tour {
 public:
  explicit Tour(const std::vector<std::size_t>& order)
      : order_(order), pos_(order.size()), n_(order.size()) {
    for (std::size_t i = 0; i < n_; ++i) pos_[order_[i]] = i;
  }
  std::size_t next(std::size_t p) const { return order_[(pos_[p] + 1) % n_]; }
  std::size_t prev(std::size_t p) const { return order_[(pos_[p] + n_ - 1) % n_]; }
  std::size_t pos(std::size_t p) const { return pos_[p]; }
  std::size_t size() const { return n_; }
  // Forward distance from position i to position j.
  std::size_t span(std::size_t i, std::size_t j) const { return (j + n_ - i) % n_; }

  // Reverses the path from position i forward to position j, both included.
  void reverse(std::size_t i, std::size_t j) {
    const std::size_t len = span(i, j) + 1;
    for (std::size_t k = 0; k < len / 2; ++k) {
      const std::size_t a = (i + k) % n_, b = (j + n_ - k) % n_;
      std::swap(order_[a], order_[b]);
      pos_[order_[a]] = a;
      pos_[order_[b]] = b;
    }
  }
  // 2-opt: replaces edges (a, next a) and (c, next c) by (a, c) and (next a, next c), reversing
  // whichever side of the cycle is shorter.
  void two_opt(std::size_t a, std::size_t c) {
    const std::size_t b = next(a), d = next(c);
    if (span(pos_[b], pos_[c]) <= span(pos_[d], pos_[a]))
      reverse(pos_[b], pos_[c]);
    else
      reverse(pos_[d], pos_[a]);
  }
  // Moves the path s1..s2 (s1 before s2) between c and d = next(c), keeping its direction
  // (c s1 … s2 d) or turning it (c s2 … s1 d). Done with reversals over the shorter way round.
  void move_segment(std::size_t s1, std::size_t s2, std::size_t c, bool turned) {
    const std::size_t i = pos_[s1], j = pos_[s2], k = pos_[c], k1 = (k + 1) % n_;
    if (span(j, k) <= span(k1, i)) {
      // … p [S] nx … c d … : S B → B S (or B S^R), B = nx … c.
      const std::size_t b0 = (j + 1) % n_;
      if (!turned) reverse(i, j);
      reverse(b0, k);
      reverse(i, k);
    } else {
      // … c [B'] [S] nx … : B' S → S B' (or S^R B'), B' = d … p.
      const std::size_t b1 = (i + n_ - 1) % n_;
      reverse(k1, b1);
      if (!turned) reverse(i, j);
      reverse(k1, j);
    }
  }
  std::vector<std::size_t> rotated_to(std::size_t start) const {
    std::vector<std::size_t> out(n_);
    for (std::size_t k = 0; k < n_; ++k) out[k] = order_[(pos_[start] + k) % n_];
    return out;
  }

 private:
  std::vector<std::size_t> order_;
  std::vector<std::size_t> pos_;
  std::size_t n_;
};

class LocalSearch {
 public:
  LocalSearch(Tour& tour, const MoveCost& cost, std::vector<std::vector<std::size_t>> neighbours)
      : t_(tour), cost_(cost), nb_(std::move(neighbours)), queued_(tour.size(), true) {
    for (std::size_t p = 0; p < tour.size(); ++p) queue_.push_back(p);
  }

  void run() {
    while (!queue_.empty()) {
      const std::size_t a = queue_.front();
      queue_.pop_front();
      queued_[a] = false;
      if (two_opt(a) || or_opt(a)) wake(a);
    }
  }

 private:
  void wake(std::size_t p) {
    if (!queued_[p]) queued_[p] = true, queue_.push_back(p);
  }

  // Both 2-opt moves that give `a` an edge to one of its neighbours.
  bool two_opt(std::size_t a) {
    for (int side = 0; side < 2; ++side) {
      const std::size_t b = side == 0 ? t_.next(a) : t_.prev(a);
      const double ab = cost_(a, b);
      for (std::size_t c : nb_[a]) {
        const double ac = cost_(a, c);
        if (ac >= ab) break;  // neighbours come cheapest first
        const std::size_t d = side == 0 ? t_.next(c) : t_.prev(c);
        if (c == b || d == a) continue;
        const double gain = ab + cost_(c, d) - ac - cost_(b, d);
        if (gain <= kMinGain) continue;
        if (side == 0)
          t_.two_opt(a, c);
        else
          t_.two_opt(b, d);  // edges (b, a) and (d, c) seen from their first ends
        for (std::size_t p : {b, c, d}) wake(p);
        return true;
      }
    }
    return false;
  }

  // Moves a segment of 1–3 points that begins or ends at `a` next to a neighbour of its ends.
  bool or_opt(std::size_t a) {
    if (t_.size() < 5) return false;
    for (std::size_t len = 1; len <= 3; ++len)
      for (int side = 0; side < 2; ++side) {
        // The segment s1 … s2 in tour order, with `a` at its front (side 0) or its back.
        std::size_t s1 = a, s2 = a;
        for (std::size_t k = 1; k < len; ++k) (side == 0 ? s2 : s1) = side == 0 ? t_.next(s2) : t_.prev(s1);
        if (try_move(s1, s2, len)) return true;
      }
    return false;
  }

  bool in_segment(std::size_t q, std::size_t s1, std::size_t len) const {
    return t_.span(t_.pos(s1), t_.pos(q)) < len;
  }

  bool try_move(std::size_t s1, std::size_t s2, std::size_t len) {
    const std::size_t p = t_.prev(s1), nx = t_.next(s2);
    if (p == s2 || nx == s1 || p == nx) return false;
    const double removal = cost_(p, s1) + cost_(s2, nx) - cost_(p, nx);
    if (removal <= kMinGain) return false;
    for (std::size_t end : {s1, s2})
      for (std::size_t c0 : nb_[end]) {
        if (cost_(end, c0) >= removal) break;  // cannot pay for the insertion
        if (in_segment(c0, s1, len)) continue;
        // Insert between c0 and either of its tour neighbours.
        for (int side = 0; side < 2; ++side) {
          const std::size_t c = side == 0 ? c0 : t_.prev(c0);
          const std::size_t d = t_.next(c);
          if (in_segment(c, s1, len) || in_segment(d, s1, len)) continue;
          const double cd = cost_(c, d);
          const double keep = cost_(c, s1) + cost_(s2, d) - cd;
          const double turn = cost_(c, s2) + cost_(s1, d) - cd;
          const bool turned = turn < keep;
          if (removal - (turned ? turn : keep) <= kMinGain) continue;
          t_.move_segment(s1, s2, c, turned);
          for (std::size_t q : {p, nx, s1, s2, c, d}) wake(q);
          return true;
        }
      }
    return false;
  }

  Tour& t_;
  const MoveCost& cost_;
  std::vector<std::vector<std::size_t>> nb_;
  std::deque<std::size_t> queue_;
  std::vector<bool> queued_;
};

}  // namespace

std::vector<std::size_t> nearest_neighbour_tour(const MoveCost& cost, std::size_t start) {
  std::vector<std::size_t> tour;
  if (cost.size() == 0) return tour;
  PointGrid grid(cost);
  tour.reserve(cost.size());
  std::size_t at = start;
  grid.visit(at);
  tour.push_back(at);
  for (std::size_t k = 1; k < cost.size(); ++k) {
    at = grid.nearest_unvisited(at);
    grid.visit(at);
    tour.push_back(at);
  }
  return tour;
}

void improve_tour(std::vector<std::size_t>& tour, const MoveCost& cost, std::size_t start,
                  const TourOptions& options) {
  if (tour.size() < 4) return;
  Tour t(tour);
  LocalSearch(t, cost, PointGrid(cost).neighbour_lists(options.neighbours)).run();
  tour = t.rotated_to(start);
}

double tour_time_s(const std::vector<std::size_t>& tour, const MoveCost& cost) {
  double s = 0;
  for (std::size_t i = 0; i < tour.size(); ++i) s += cost(tour[i], tour[(i + 1) % tour.size()]);
  return s;
}

}  // namespace mark

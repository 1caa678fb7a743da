#include "marker/peen/tour_search.hpp"

#include <algorithm>
#include <deque>
#include <random>

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
  // (No % in these: they run millions of times and a division costs more than the rest.)
  std::size_t next(std::size_t p) const { return order_[wrap(pos_[p] + 1)]; }
  std::size_t prev(std::size_t p) const { return order_[pos_[p] == 0 ? n_ - 1 : pos_[p] - 1]; }
  std::size_t pos(std::size_t p) const { return pos_[p]; }
  std::size_t size() const { return n_; }
  // Forward distance from position i to position j.
  std::size_t span(std::size_t i, std::size_t j) const { return j >= i ? j - i : j + n_ - i; }
  // A position one past the end comes back to the start.
  std::size_t wrap(std::size_t i) const { return i >= n_ ? i - n_ : i; }

  // Reverses the path from position i forward to position j, both included. Every change to the
  // tour is a reversal, so a log of them undoes any sequence of moves.
  void reverse(std::size_t i, std::size_t j) {
    if (log_) log_->push_back({i, j});
    const std::size_t len = span(i, j) + 1;
    std::size_t a = i, b = j;
    for (std::size_t k = 0; k < len / 2; ++k) {
      std::swap(order_[a], order_[b]);
      pos_[order_[a]] = a;
      pos_[order_[b]] = b;
      a = a + 1 == n_ ? 0 : a + 1;
      b = b == 0 ? n_ - 1 : b - 1;
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
  // Positions two_opt(a, c) reverses.
  std::size_t two_opt_work(std::size_t a, std::size_t c) const {
    const std::size_t b = next(a), d = next(c);
    return std::min(span(pos_[b], pos_[c]), span(pos_[d], pos_[a])) + 1;
  }
  // Positions move_segment(s1, s2, c, …) reverses beyond the segment itself.
  std::size_t move_work(std::size_t s1, std::size_t s2, std::size_t c) const {
    const std::size_t i = pos_[s1], j = pos_[s2], k = pos_[c];
    return 2 * std::min(span(j, k), span(wrap(k + 1), i));
  }
  // Moves the path s1..s2 (s1 before s2) between c and d = next(c), keeping its direction
  // (c s1 … s2 d) or turning it (c s2 … s1 d). Done with reversals over the shorter way round.
  void move_segment(std::size_t s1, std::size_t s2, std::size_t c, bool turned) {
    const std::size_t i = pos_[s1], j = pos_[s2], k = pos_[c], k1 = wrap(k + 1);
    if (span(j, k) <= span(k1, i)) {
      // … p [S] nx … c d … : S B → B S (or B S^R), B = nx … c.
      const std::size_t b0 = wrap(j + 1);
      if (!turned) reverse(i, j);
      reverse(b0, k);
      reverse(i, k);
    } else {
      // … c [B'] [S] nx … : B' S → S B' (or S^R B'), B' = d … p.
      const std::size_t b1 = i == 0 ? n_ - 1 : i - 1;
      reverse(k1, b1);
      if (!turned) reverse(i, j);
      reverse(k1, j);
    }
  }
  void start_log(std::vector<std::pair<std::size_t, std::size_t>>* log) { log_ = log; }
  void undo(const std::vector<std::pair<std::size_t, std::size_t>>& log) {
    auto* keep = log_;
    log_ = nullptr;
    for (auto it = log.rbegin(); it != log.rend(); ++it) reverse(it->first, it->second);
    log_ = keep;
  }
  std::size_t at(std::size_t position) const { return order_[position % n_]; }

  std::vector<std::size_t> rotated_to(std::size_t start) const {
    std::vector<std::size_t> out(n_);
    for (std::size_t k = 0; k < n_; ++k) out[k] = order_[(pos_[start] + k) % n_];
    return out;
  }

 private:
  std::vector<std::size_t> order_;
  std::vector<std::size_t> pos_;
  std::size_t n_;
  std::vector<std::pair<std::size_t, std::size_t>>* log_ = nullptr;
};

class LocalSearch {
 public:
  LocalSearch(Tour& tour, const MoveCost& cost, std::vector<std::vector<std::size_t>> neighbours,
              const Progress& progress)
      : t_(tour), cost_(cost), nb_(std::move(neighbours)), queued_(tour.size(), false), progress_(progress) {}

  void wake(std::size_t p) {
    if (!queued_[p]) queued_[p] = true, queue_.push_back(p);
  }
  // Moves that would reverse more than this many tour positions are skipped: keeps the work of
  // a local search after a kick local (the first full search runs without a limit).
  void limit_reversals(std::size_t positions) { max_reversal_ = positions; }

  // Applies improving moves around the woken points until none is left; returns the time saved.
  double run() {
    double saved = 0;
    std::size_t steps = 0;
    while (!queue_.empty()) {
      if (++steps % 1024 == 0) progress_.step("peen: improving the needle path (points looked at)", steps, 0);
      const std::size_t a = queue_.front();
      queue_.pop_front();
      queued_[a] = false;
      double gain = two_opt(a);
      if (gain <= 0) gain = or_opt(a);
      if (gain > 0) saved += gain, wake(a);
    }
    return saved;
  }

 private:
  // Both 2-opt moves that give `a` an edge to one of its neighbours; returns the gain (0: none).
  double two_opt(std::size_t a) {
    for (int side = 0; side < 2; ++side) {
      const std::size_t b = side == 0 ? t_.next(a) : t_.prev(a);
      const double ab = cost_(a, b);
      for (std::size_t c : nb_[a]) {
        const double ac = cost_(a, c);
        if (ac >= ab) break;  // neighbours come cheapest first
        const std::size_t d = side == 0 ? t_.next(c) : t_.prev(c);
        if (c == b || d == a) continue;
        if (t_.two_opt_work(side == 0 ? a : b, side == 0 ? c : d) > max_reversal_) continue;
        const double gain = ab + cost_(c, d) - ac - cost_(b, d);
        if (gain <= kMinGain) continue;
        if (side == 0)
          t_.two_opt(a, c);
        else
          t_.two_opt(b, d);  // edges (b, a) and (d, c) seen from their first ends
        for (std::size_t p : {b, c, d}) wake(p);
        return gain;
      }
    }
    return 0;
  }

  // Moves a segment of 1–3 points that begins or ends at `a` next to a neighbour of its ends.
  double or_opt(std::size_t a) {
    if (t_.size() < 5) return 0;
    for (std::size_t len = 1; len <= 3; ++len)
      for (int side = 0; side < 2; ++side) {
        // The segment s1 … s2 in tour order, with `a` at its front (side 0) or its back.
        std::size_t s1 = a, s2 = a;
        for (std::size_t k = 1; k < len; ++k) (side == 0 ? s2 : s1) = side == 0 ? t_.next(s2) : t_.prev(s1);
        if (const double gain = try_move(s1, s2, len); gain > 0) return gain;
      }
    return 0;
  }

  bool in_segment(std::size_t q, std::size_t s1, std::size_t len) const {
    return t_.span(t_.pos(s1), t_.pos(q)) < len;
  }

  double try_move(std::size_t s1, std::size_t s2, std::size_t len) {
    const std::size_t p = t_.prev(s1), nx = t_.next(s2);
    if (p == s2 || nx == s1 || p == nx) return 0;
    const double removal = cost_(p, s1) + cost_(s2, nx) - cost_(p, nx);
    if (removal <= kMinGain) return 0;
    for (std::size_t end : {s1, s2})
      for (std::size_t c0 : nb_[end]) {
        if (cost_(end, c0) >= removal) break;  // cannot pay for the insertion
        if (in_segment(c0, s1, len)) continue;
        // Insert between c0 and either of its tour neighbours.
        for (int side = 0; side < 2; ++side) {
          const std::size_t c = side == 0 ? c0 : t_.prev(c0);
          const std::size_t d = t_.next(c);
          if (in_segment(c, s1, len) || in_segment(d, s1, len)) continue;
          if (t_.move_work(s1, s2, c) > max_reversal_) continue;
          const double cd = cost_(c, d);
          const double keep = cost_(c, s1) + cost_(s2, d) - cd;
          const double turn = cost_(c, s2) + cost_(s1, d) - cd;
          const bool turned = turn < keep;
          const double gain = removal - (turned ? turn : keep);
          if (gain <= kMinGain) continue;
          t_.move_segment(s1, s2, c, turned);
          for (std::size_t q : {p, nx, s1, s2, c, d}) wake(q);
          return gain;
        }
      }
    return 0;
  }

  Tour& t_;
  const MoveCost& cost_;
  std::vector<std::vector<std::size_t>> nb_;
  std::deque<std::size_t> queue_;
  std::vector<bool> queued_;
  std::size_t max_reversal_ = static_cast<std::size_t>(-1);
  const Progress& progress_;
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
  const std::size_t n = tour.size();
  if (n < 4) return;
  Tour t(tour);
  LocalSearch search(t, cost, PointGrid(cost).neighbour_lists(options.neighbours), *options.progress);
  for (std::size_t p = 0; p < n; ++p) search.wake(p);
  search.run();
  if (n < 8) {
    tour = t.rotated_to(start);
    return;
  }

  // Iterated local search: a local double bridge (swap two neighbouring stretches of the tour,
  // a move 2-opt and Or-opt cannot undo), local search around the cut points, and the result kept
  // unless it is slower. Plateaus of equal move times are common on a dot grid; accepting equal
  // tours lets the search walk across them.
  search.limit_reversals(4 * options.kick_span);
  std::mt19937_64 random(options.seed);
  const std::size_t window = std::min<std::size_t>(options.kick_span, n - 1);
  const std::size_t kicks = std::min(options.kicks_per_point * n, options.max_kicks);
  std::vector<std::pair<std::size_t, std::size_t>> log;
  for (std::size_t k = 0; k < kicks; ++k) {
    if (k % 64 == 0) options.progress->step("peen: kicking the needle path", k, kicks);
    // Cut points i < j < l inside a window: A [i+1..j] [j+1..l] D → A [j+1..l] [i+1..j] D.
    const std::size_t i = random() % n;
    std::size_t j = 1 + random() % (window - 1), l = 1 + random() % (window - 1);
    if (j == l) continue;
    if (j > l) std::swap(j, l);
    const std::size_t a = t.at(i), b = t.at(i + 1), c = t.at(i + j), d = t.at(i + j + 1),
                      e = t.at(i + l), f = t.at(i + l + 1);
    const double delta = cost(a, d) + cost(e, b) + cost(c, f) - cost(a, b) - cost(c, d) - cost(e, f);
    log.clear();
    t.start_log(&log);
    const std::size_t p1 = (i + 1) % n, pj = (i + j) % n, pj1 = (i + j + 1) % n, pl = (i + l) % n;
    t.reverse(p1, pj);
    t.reverse(pj1, pl);
    t.reverse(p1, pl);
    for (std::size_t q : {a, b, c, d, e, f}) search.wake(q);
    const double saved = search.run();
    t.start_log(nullptr);
    if (delta - saved > kMinGain) t.undo(log);
  }
  tour = t.rotated_to(start);
}

double tour_time_s(const std::vector<std::size_t>& tour, const MoveCost& cost) {
  double s = 0;
  for (std::size_t i = 0; i < tour.size(); ++i) s += cost(tour[i], tour[(i + 1) % tour.size()]);
  return s;
}

}  // namespace mark

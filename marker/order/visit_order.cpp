// Nearest neighbour + 2-opt + relocation over items with separate entry and exit points. Items
// are asymmetric in general (an open stroke cut in an even number of passes enters and leaves at
// the same end), so a 2-opt move is costed with the reversed links of the run, not by symmetry.
#include "marker/order/visit_order.hpp"

#include <limits>

namespace mark {
namespace {

constexpr double kGainEps = 1e-9;  // mm: smaller gains are rounding, not improvement
constexpr int kMaxSweeps = 100;

const Point& entry_of(const VisitItem& it, bool rev) { return rev ? it.entry_reversed : it.entry; }
const Point& exit_of(const VisitItem& it, bool rev) { return rev ? it.exit_reversed : it.exit; }

class Tour {
 public:
  Tour(const std::vector<VisitItem>& items, const Point& start, std::vector<VisitStep> order)
      : items_(items), start_(start), s_(std::move(order)) {}

  std::vector<VisitStep>& steps() { return s_; }

  // Exit point before position k (the start point before position 0).
  Point exit_before(std::size_t k) const {
    return k == 0 ? start_ : exit_of(items_[s_[k - 1].item], s_[k - 1].reversed);
  }
  double link(const Point& from, const VisitStep& to) const {
    return (entry_of(items_[to.item], to.reversed) - from).norm();
  }
  Point exit_at(const VisitStep& st) const { return exit_of(items_[st.item], st.reversed); }

  bool two_opt_sweep() {
    const std::size_t n = s_.size();
    if (n < 2) return false;
    bool improved = false;
    // forward[k]: link from s[k-1] into s[k]; backward[k]: link from flip(s[k]) into flip(s[k-1]).
    std::vector<double> fwd(n + 1, 0.0), bwd(n + 1, 0.0);
    std::vector<int> fixed(n + 1, 0);
    auto rebuild = [&] {
      for (std::size_t k = 1; k < n; ++k) {
        const VisitStep a = s_[k - 1], b = s_[k];
        fwd[k + 1] = fwd[k] + link(exit_at(a), b);
        const VisitStep fb{b.item, !b.reversed}, fa{a.item, !a.reversed};
        bwd[k + 1] = bwd[k] + link(exit_at(fb), fa);
      }
      for (std::size_t k = 0; k < n; ++k) fixed[k + 1] = fixed[k] + (items_[s_[k].item].reversible ? 0 : 1);
    };
    rebuild();
    for (std::size_t i = 0; i < n; ++i) {
      for (std::size_t j = i + 1; j < n; ++j) {
        if (fixed[j + 1] - fixed[i] > 0) break;  // the run contains an item that cannot reverse
        const Point before = exit_before(i);
        const VisitStep si = s_[i], sj = s_[j];
        const VisitStep fi{si.item, !si.reversed}, fj{sj.item, !sj.reversed};
        // inner links over k = i+1..j live at prefix indices k+1
        double old_cost = link(before, si) + (fwd[j + 1] - fwd[i + 1]);
        double new_cost = link(before, fj) + (bwd[j + 1] - bwd[i + 1]);
        if (j + 1 < n) {
          old_cost += link(exit_at(sj), s_[j + 1]);
          new_cost += link(exit_at(fi), s_[j + 1]);
        }
        if (new_cost < old_cost - kGainEps) {
          for (std::size_t a = i, b = j; a < b; ++a, --b) std::swap(s_[a], s_[b]);
          for (std::size_t k = i; k <= j; ++k) s_[k].reversed = !s_[k].reversed;
          rebuild();
          improved = true;
        }
      }
    }
    return improved;
  }

  bool relocate_sweep() {
    bool improved = false;
    for (std::size_t i = 0; i < s_.size(); ++i) {
      const std::size_t n = s_.size();
      const VisitStep si = s_[i];
      const Point before = exit_before(i);
      double removal_gain = link(before, si);
      if (i + 1 < n) removal_gain += link(exit_at(si), s_[i + 1]) - link(before, s_[i + 1]);
      // Try every gap of the tour without item i; gap g sits before remaining position g.
      std::vector<VisitStep> rest;
      rest.reserve(n - 1);
      for (std::size_t k = 0; k < n; ++k)
        if (k != i) rest.push_back(s_[k]);
      double best = removal_gain - kGainEps;
      std::size_t best_gap = n;
      bool best_rev = false;
      for (std::size_t g = 0; g <= rest.size(); ++g) {
        const Point from = g == 0 ? start_ : exit_at(rest[g - 1]);
        for (bool rev : {false, true}) {
          if (rev && !items_[si.item].reversible) continue;
          const VisitStep c{si.item, rev ? !si.reversed : si.reversed};
          double cost = link(from, c);
          if (g < rest.size()) cost += link(exit_at(c), rest[g]) - link(from, rest[g]);
          if (cost < best) {
            best = cost;
            best_gap = g;
            best_rev = rev;
          }
        }
      }
      if (best_gap != n) {
        VisitStep moved{si.item, best_rev ? !si.reversed : si.reversed};
        rest.insert(rest.begin() + static_cast<std::ptrdiff_t>(best_gap), moved);
        s_ = std::move(rest);
        improved = true;
      }
    }
    return improved;
  }

 private:
  const std::vector<VisitItem>& items_;
  Point start_;
  std::vector<VisitStep> s_;
};

std::vector<VisitStep> nearest_neighbour(const std::vector<VisitItem>& items, const Point& start) {
  std::vector<VisitStep> order;
  std::vector<bool> used(items.size(), false);
  Point at = start;
  for (std::size_t round = 0; round < items.size(); ++round) {
    double best = std::numeric_limits<double>::infinity();
    VisitStep pick;
    for (std::size_t k = 0; k < items.size(); ++k) {
      if (used[k]) continue;
      for (bool rev : {false, true}) {
        if (rev && !items[k].reversible) continue;
        const double d = (entry_of(items[k], rev) - at).squaredNorm();
        if (d < best) {
          best = d;
          pick = {k, rev};
        }
      }
    }
    used[pick.item] = true;
    order.push_back(pick);
    at = exit_of(items[pick.item], pick.reversed);
  }
  return order;
}

}  // namespace

double travel_length(const std::vector<VisitItem>& items, const std::vector<VisitStep>& order,
                     const Point& start) {
  double total = 0;
  Point at = start;
  for (const VisitStep& st : order) {
    total += (entry_of(items[st.item], st.reversed) - at).norm();
    at = exit_of(items[st.item], st.reversed);
  }
  return total;
}

std::vector<VisitStep> plan_visit_order(const std::vector<VisitItem>& items, const Point& start) {
  std::vector<VisitStep> given;
  for (std::size_t k = 0; k < items.size(); ++k) given.push_back({k, false});
  std::vector<VisitStep> nn = nearest_neighbour(items, start);
  // Start from the better of the given order and nearest neighbour: text order is often already
  // good for letters, and the improvement moves below never make a tour longer.
  Tour tour(items, start,
            travel_length(items, nn, start) < travel_length(items, given, start) ? nn : given);
  for (int sweep = 0; sweep < kMaxSweeps; ++sweep) {
    const bool a = tour.two_opt_sweep();
    const bool b = tour.relocate_sweep();
    if (!a && !b) break;
  }
  return tour.steps();
}

}  // namespace mark

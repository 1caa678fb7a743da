// Visiting order: never longer than the given order, finds the obvious optimum on small cases,
// reverses strokes when that saves travel, keeps fixed items unreversed, and copes with the
// asymmetric items of even-pass strokes.
#include "marker/order/visit_order.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <random>

namespace mark {
namespace {

TEST(VisitOrder, ReversesStrokesToChainThem) {
  // Three collinear strokes given backwards and out of order: the best tour runs them end to end.
  std::vector<VisitItem> items = {VisitItem::stroke({3, 0}, {2, 0}), VisitItem::stroke({1, 0}, {0, 0}),
                                  VisitItem::stroke({5, 0}, {4, 0})};
  const std::vector<VisitStep> order = plan_visit_order(items, Point(0, 0));
  EXPECT_NEAR(travel_length(items, order, Point(0, 0)), 2.0, 1e-12);  // two 1 mm gaps
  ASSERT_EQ(order.size(), 3u);
  EXPECT_EQ(order[0].item, 1u);
  EXPECT_TRUE(order[0].reversed);
}

TEST(VisitOrder, FixedItemsAreNeverReversed) {
  std::vector<VisitItem> items = {VisitItem::fixed({10, 0}, {0, 0}), VisitItem::fixed({0, 5}, {10, 5})};
  for (const VisitStep& s : plan_visit_order(items, Point(0, 0))) EXPECT_FALSE(s.reversed);
}

TEST(VisitOrder, NeverWorseThanGivenOrNearestNeighbourAndBeatsItOnRandomStrokes) {
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(0, 100);
  double given_total = 0, planned_total = 0;
  for (int trial = 0; trial < 20; ++trial) {
    std::vector<VisitItem> items;
    for (int k = 0; k < 60; ++k) {
      const Point a(u(rng), u(rng));
      items.push_back(VisitItem::stroke(a, a + Point(u(rng) / 20, u(rng) / 20)));
    }
    std::vector<VisitStep> given;
    for (std::size_t k = 0; k < items.size(); ++k) given.push_back({k, false});
    const std::vector<VisitStep> planned = plan_visit_order(items, Point(0, 0));
    // Every item exactly once.
    std::vector<std::size_t> seen;
    for (const VisitStep& s : planned) seen.push_back(s.item);
    std::sort(seen.begin(), seen.end());
    for (std::size_t k = 0; k < seen.size(); ++k) ASSERT_EQ(seen[k], k);
    given_total += travel_length(items, given, Point(0, 0));
    planned_total += travel_length(items, planned, Point(0, 0));
  }
  // Random order of 60 points in a 100 mm square travels ~52 mm per hop; a good tour far less.
  EXPECT_LT(planned_total, 0.25 * given_total);
}

TEST(VisitOrder, EvenPassStrokesReturnToTheirStart) {
  // An open stroke cut in two passes comes back where it started: entry = exit on each end.
  std::vector<VisitItem> items;
  for (int k = 0; k < 5; ++k) {
    const Point a(10.0 * k, 0), b(10.0 * k, 8);
    items.push_back({a, a, true, b, b});
  }
  const std::vector<VisitStep> order = plan_visit_order(items, Point(0, 0));
  EXPECT_NEAR(travel_length(items, order, Point(0, 0)), 40.0, 1e-9);  // along the bottom ends
}

}  // namespace
}  // namespace mark

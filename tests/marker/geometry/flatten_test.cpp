// The one flattening every stage uses: pieces within the stated chord tolerance of the exact
// curve (measured against the element's own point_at, densely), points spaced as asked, the
// exact end, and a bounded piece count for absurd tolerances.
#include "marker/geometry/flatten.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace mark {
namespace {

// Largest distance from the exact curve to the chords, sampled at 64 points per chord.
double worst_chord_gap(const Element& e, std::size_t n) {
  const std::vector<Point> pts = pieces_of(e, n);
  double worst = 0;
  for (std::size_t k = 0; k < n; ++k)
    for (int i = 1; i < 64; ++i) {
      const double t = (static_cast<double>(k) + i / 64.0) / static_cast<double>(n);
      const Point p = e.point_at(t);
      const Point a = pts[k], b = pts[k + 1];
      const Point ab = b - a;
      const double u = std::clamp((p - a).dot(ab) / ab.squaredNorm(), 0.0, 1.0);
      worst = std::max(worst, (p - (a + u * ab)).norm());
    }
  return worst;
}

TEST(Flatten, CircleChordsStayWithinTheTolerance) {
  for (double r : {0.05, 1.0, 25.0})
    for (double tol : {1e-4, 5e-3, 0.02}) {
      const Element arc = Element::arc({1, -2}, r, 0.3, 1.75 * std::numbers::pi, true);
      const std::size_t n = chord_count(arc, tol);
      EXPECT_LE(worst_chord_gap(arc, n), tol * (1 + 1e-6)) << "r " << r << " tol " << tol;
      // And not needlessly many: one chord fewer would leave the tolerance (when it can).
      if (n > 2) {
        EXPECT_GT(worst_chord_gap(arc, n - 1), tol * 0.9) << "r " << r << " tol " << tol;
      }
    }
}

TEST(Flatten, EllipseChordsStayWithinTheTolerance) {
  const Element el = Element::ellipse({0, 0}, 3, 0.7, 0.4, -0.2, 2.5, true);
  for (double tol : {1e-4, 1e-3, 0.01}) {
    const std::size_t n = chord_count(el, tol);
    EXPECT_LE(worst_chord_gap(el, n), tol) << tol;
  }
}

TEST(Flatten, PiecesEndExactlyOnTheElementsEnd) {
  const Element arc = Element::arc({0.3, 0.1}, 2, 1.0, -4.0, true);
  const std::vector<Point> pts = pieces_of(arc, 997);
  EXPECT_EQ(pts.front(), arc.start());
  EXPECT_EQ(pts.back(), arc.end());
  for (std::size_t k = 0; k < pts.size(); ++k)
    EXPECT_LT((pts[k] - arc.point_at(static_cast<double>(k) / 997)).norm(), 1e-12) << k;
}

TEST(Flatten, SpacedPointsAreAtMostTheStepApart) {
  const Element arc = Element::arc({0, 0}, 4, 0, 2.0, true);
  const Element line = Element::line({0, 0}, {1, 0.5}, true);
  for (const Element& e : {arc, line}) {
    const std::vector<Point> pts = pieces_of(e, spaced_count(e, 0.05));
    for (std::size_t k = 1; k < pts.size(); ++k) EXPECT_LE((pts[k] - pts[k - 1]).norm(), 0.05 + 1e-12);
  }
}

TEST(Flatten, AnAbsurdToleranceCostsABoundedNumberOfPieces) {
  const Element arc = Element::arc({0, 0}, 1e6, 0, 2 * std::numbers::pi, true);
  EXPECT_EQ(chord_count(arc, 0), kMaxPieces);
  EXPECT_EQ(chord_count(arc, std::nan("")), kMaxPieces);
  EXPECT_EQ(chord_count(Element::line({0, 0}, {1, 1}, true), 1e-12), 1u);
}

}  // namespace
}  // namespace mark

// "Continuous" dot characters: dots along the strokes of any stroke font at a dot pitch.
#include <algorithm>
#include <climits>
#include <cmath>
#include <numbers>
#include <string>
#include <unordered_map>

#include "base/error.hpp"
#include "fonts/stroke_join.hpp"
#include "marker/peen/dot_layout.hpp"

namespace mark {
namespace {

// Element parameter t where the arc length from the start reaches `s`. Lines and circular arcs
// are linear in length; elliptical arcs are inverted by bisection on the exact length.
double param_at_length(const Element& e, double s, double total) {
  if (total <= 0) return 0;
  if (e.kind() != ElementKind::ellipse) return std::clamp(s / total, 0.0, 1.0);
  double lo = 0, hi = 1;
  for (int i = 0; i < 48 && hi - lo > 1e-12; ++i) {
    const double mid = (lo + hi) / 2;
    (e.length_between(0, mid) < s ? lo : hi) = mid;
  }
  return (lo + hi) / 2;
}

// Elements of a stroke between two corners, walked by arc length.
struct SmoothRun {
  std::vector<Element> elements;
  std::vector<double> lengths;
  double length = 0;

  void add(const Element& e) {
    elements.push_back(e);
    lengths.push_back(e.length());
    length += lengths.back();
  }
  Point point_at(double s) const {
    for (std::size_t i = 0; i + 1 < elements.size(); ++i) {
      if (s <= lengths[i]) return elements[i].point_at(param_at_length(elements[i], s, lengths[i]));
      s -= lengths[i];
    }
    return elements.back().point_at(param_at_length(elements.back(), s, lengths.back()));
  }
};

// More turn than this between two elements is a corner, where a dot must fall.
constexpr double kCornerRad = 10 * std::numbers::pi / 180;

std::vector<SmoothRun> smooth_runs(const std::vector<Element>& stroke) {
  std::vector<SmoothRun> runs(1);
  for (std::size_t i = 0; i < stroke.size(); ++i) {
    if (i > 0) {
      const double c = stroke[i - 1].tangent_at(1.0).dot(stroke[i].tangent_at(0.0));
      if (std::acos(std::clamp(c, -1.0, 1.0)) > kCornerRad) runs.emplace_back();
    }
    runs.back().add(stroke[i]);
  }
  return runs;
}

// Kept dots on a hash grid of half-pitch cells: a candidate closer than half a pitch to a kept dot
// lies in one of the 3x3 cells around its own.
class DotSieve {
 public:
  explicit DotSieve(double pitch_mm) : cell_(pitch_mm / 2), min_dist2_(cell_ * cell_) {}

  bool keep(const Point& p) {
    const long cx = key(p.x()), cy = key(p.y());
    for (long dx = -1; dx <= 1; ++dx)
      for (long dy = -1; dy <= 1; ++dy) {
        auto it = cells_.find(hash(cx + dx, cy + dy));
        if (it == cells_.end()) continue;
        for (const Point& q : it->second)
          if ((q - p).squaredNorm() < min_dist2_) return false;
      }
    cells_[hash(cx, cy)].push_back(p);
    return true;
  }

 private:
  long key(double v) const { return static_cast<long>(std::floor(v / cell_)); }
  static long long hash(long x, long y) { return (static_cast<long long>(x) << 32) ^ (y & 0xffffffffLL); }

  double cell_;
  double min_dist2_;
  std::unordered_map<long long, std::vector<Point>> cells_;
};

}  // namespace

DotText dots_along_strokes(const Figure& figure, double pitch_mm) {
  if (!(pitch_mm > 0) || !std::isfinite(pitch_mm))
    throw InputError("dot pitch " + std::to_string(pitch_mm) + " mm: must be a positive length");
  DotText out;
  out.pitch_mm = pitch_mm;
  DotSieve sieve(pitch_mm);
  const double join_tol = figure.join_tolerance_mm();
  for (const PlacedGlyph& g : figure.glyphs) {
    const Affine to_local = g.placement().inverse();
    const std::size_t first = out.dots.size();
    for (const ChainedStroke& stroke : chain_strokes(g.elements, join_tol)) {
      for (const SmoothRun& run : smooth_runs(stroke.elements)) {
        const int intervals = std::max(1, static_cast<int>(std::ceil(run.length / pitch_mm - 1e-9)));
        for (int k = 0; k <= intervals; ++k) {
          const Point p = run.point_at(run.length * k / intervals);
          if (!sieve.keep(p)) continue;
          const Point local = to_local * p;
          out.dots.push_back({p, out.characters,
                              {static_cast<int>(std::lround(local.x() / pitch_mm)),
                               static_cast<int>(std::lround(-local.y() / pitch_mm))}});
        }
      }
    }
    if (out.dots.size() == first) continue;
    // Cells start at the top-left corner of the character's own dots.
    int min_col = INT_MAX, min_row = INT_MAX;
    for (std::size_t i = first; i < out.dots.size(); ++i) {
      min_col = std::min(min_col, out.dots[i].cell.col);
      min_row = std::min(min_row, out.dots[i].cell.row);
    }
    for (std::size_t i = first; i < out.dots.size(); ++i) {
      out.dots[i].cell.col -= min_col;
      out.dots[i].cell.row -= min_row;
    }
    // Cell (col, row) → glyph mm ((col + min_col)·pitch, −(row + min_row)·pitch) → field mm.
    Affine cell_to_local = Affine::Identity();
    cell_to_local.linear() << pitch_mm, 0.0, 0.0, -pitch_mm;
    cell_to_local.translation() = Point(min_col * pitch_mm, -min_row * pitch_mm);
    out.cell_frames.push_back(g.placement() * cell_to_local);
    ++out.characters;
  }
  return out;
}

}  // namespace mark

#include "marker/production/object_clearance.hpp"

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <unordered_map>

#include "base/error.hpp"
#include "marker/production/part_texts.hpp"

namespace mark {
namespace {

constexpr double kSampleStep_mm = 0.05;  // as PlacedCode::first_intrusion samples the ink

std::vector<Point> ink_points(const Figure& figure) {
  std::vector<Point> points;
  for (const PlacedGlyph& g : figure.glyphs)
    for (const Element& e : g.elements) {
      if (!e.laser()) continue;
      const int n = std::max(1, static_cast<int>(std::ceil(e.length() / kSampleStep_mm)));
      for (int k = 0; k <= n; ++k) points.push_back(e.point_at(static_cast<double>(k) / n));
    }
  return points;
}

// Points binned in square cells of the spot diameter: a point within one diameter of a query
// lies in the query's cell or one of its eight neighbours.
class InkGrid {
 public:
  InkGrid(const std::vector<Point>& points, double cell_mm) : cell_(cell_mm) {
    for (const Point& p : points) cells_[key(cell_of(p.x()), cell_of(p.y()))].push_back(p);
  }
  std::optional<Point> within(const Point& q, double d) const {
    const std::int64_t cx = cell_of(q.x()), cy = cell_of(q.y());
    for (std::int64_t i = cx - 1; i <= cx + 1; ++i)
      for (std::int64_t j = cy - 1; j <= cy + 1; ++j) {
        const auto it = cells_.find(key(i, j));
        if (it == cells_.end()) continue;
        for (const Point& p : it->second)
          if ((p - q).norm() < d) return p;
      }
    return std::nullopt;
  }

 private:
  std::int64_t cell_of(double v) const { return static_cast<std::int64_t>(std::floor(v / cell_)); }
  static std::uint64_t key(std::int64_t i, std::int64_t j) {
    return (static_cast<std::uint64_t>(i) << 32) ^ (static_cast<std::uint64_t>(j) & 0xffffffffu);
  }
  double cell_;
  std::unordered_map<std::uint64_t, std::vector<Point>> cells_;
};

std::string at(const Point& p) {
  char s[64];
  std::snprintf(s, sizeof s, "(%.3f, %.3f) mm", p.x(), p.y());
  return s;
}

std::string named(const JobFile& job, std::size_t i) { return "object \"" + job.objects[i].name + "\""; }

}  // namespace

void check_objects_apart(const JobFile& job, const std::vector<CompiledJob>& compiled) {
  if (compiled.size() < 2) return;  // one object meets nothing: no ink sampled on every part
  const double spot_mm = job.head.spot_diameter_um / 1000;
  std::vector<std::vector<Point>> ink;
  std::vector<InkGrid> grids;
  for (const CompiledJob& c : compiled) {
    ink.push_back(ink_points(c.figure));
    grids.emplace_back(ink.back(), spot_mm);
  }
  for (std::size_t a = 0; a < compiled.size(); ++a)
    for (std::size_t b = 0; b < compiled.size(); ++b) {
      if (a == b) continue;
      // b's ink in a's quiet zone (the symbol included): a reader needs it bare.
      for (const PlacedCode& code : compiled[a].codes)
        for (const PlacedGlyph& g : compiled[b].figure.glyphs)
          if (const auto p = code.first_intrusion(g.elements))
            throw InputError(object_place(job, a) + "its code's quiet zone is marked by " + named(job, b) + " at " +
                             at(*p) + "; move the objects apart");
      if (b < a || !compiled[a].codes.empty() || !compiled[b].codes.empty() || job.overlap_allowed(a, b)) continue;
      // Two marks without a code: inks closer than the spot touch.
      for (const Point& p : ink[a])
        if (const auto q = grids[b].within(p, spot_mm))
          throw InputError(object_place(job, a) + "its ink touches " + named(job, b) + "'s at " + at(p) +
                           " (strokes " + std::to_string(static_cast<int>(std::lround((*q - p).norm() * 1000))) +
                           " µm apart, the spot is " + std::to_string(static_cast<int>(std::lround(spot_mm * 1000))) +
                           " µm); move the objects apart");
    }
}

}  // namespace mark

#include "marker/cnc/letter_contacts.hpp"

#include "marker/geometry/clipper_paths.hpp"

namespace mark {
namespace {

constexpr double kMinSharedMm2 = 1e-6;  // below this, round-off of the polygons, not contact

}  // namespace

std::vector<LetterContact> touching_letters(const Figure& figure, double stroke_width_mm) {
  std::vector<ClipperLib::Paths> regions(figure.glyphs.size());
  std::vector<Box> bounds(figure.glyphs.size());
  for (std::size_t i = 0; i < figure.glyphs.size(); ++i) {
    ClipperLib::Paths strokes;
    append_glyph_polylines(figure.glyphs[i], kChordTolMm, strokes);
    if (strokes.empty()) continue;
    regions[i] = grow_strokes(strokes, stroke_width_mm / 2, kArcTolMm);
    for (const ClipperLib::Path& p : regions[i])
      for (const ClipperLib::IntPoint& q : p) bounds[i].add(to_mm(q));
  }
  std::vector<LetterContact> out;
  for (std::size_t i = 0; i < regions.size(); ++i)
    for (std::size_t j = i + 1; j < regions.size(); ++j) {
      if (regions[i].empty() || regions[j].empty()) continue;
      const Box& a = bounds[i];
      const Box& b = bounds[j];
      if (a.max.x() < b.min.x() || b.max.x() < a.min.x() || a.max.y() < b.min.y() || b.max.y() < a.min.y())
        continue;
      const ClipperLib::Paths shared = intersection(regions[i], regions[j]);
      const double area = area_mm2(shared);
      if (area <= kMinSharedMm2) continue;
      Box where;
      for (const ClipperLib::Path& p : shared)
        for (const ClipperLib::IntPoint& q : p) where.add(to_mm(q));
      out.push_back({i, j, area, where.center()});
    }
  return out;
}

}  // namespace mark

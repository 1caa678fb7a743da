#pragma once
// Planning the next part of a series: a figure relaid out by relayout_text() differs from the
// last one only in some glyphs (a serial number's last digits). In glyph stroke order the plan
// is a sequence per glyph, so the commands of every glyph before the first changed one are
// kept and only the rest is planned again, with the running bounds, stroke count and jump
// length kept per glyph. The result equals plan_figure()'s. Stroke order `shortest` reorders
// across glyphs and is planned whole.
#include <vector>

#include "marker/plan/plan.hpp"

namespace mark {

class Replanner {
 public:
  explicit Replanner(const Pen& pen, StrokeOrder order = StrokeOrder::glyph,
                     const Point& home = Point(0, 0));

  // The plan of `figure`; valid until the next update.
  const Plan& update(const Figure& figure);
  // Everything the mirrors pass (= plan().bounds()), from the kept prefix and the new commands.
  const Box& bounds() const { return bounds_; }
  const Plan& plan() const { return plan_; }
  // Glyphs planned again in the last update (for tests and benchmarks).
  std::size_t replanned_glyphs() const { return replanned_; }

 private:
  struct GlyphKey {
    char32_t code_point;
    std::size_t shape;
    Point origin;
    double rotation;
    bool operator==(const GlyphKey&) const = default;
  };
  // State of the plan before glyph g's commands.
  struct Before {
    std::size_t command = 0;
    std::size_t strokes = 0;
    double jump_mm = 0;
    Point pen_at;   // last stroke end (home at first)
    Box bounds;
  };

  Pen pen_;
  StrokeOrder order_;
  Point home_;
  Plan plan_;
  Box bounds_;
  std::vector<GlyphKey> keys_;
  std::vector<Before> before_;
  std::vector<Stroke> strokes_;  // scratch
  std::size_t replanned_ = 0;
};

}  // namespace mark

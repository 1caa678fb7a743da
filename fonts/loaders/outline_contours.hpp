#pragma once
// One outline glyph's contours (FreeType's decomposition: move, line, conic, cubic) turned into
// the elements every loader produces: each contour a closed lit stroke of lines and circular arcs
// (Béziers biarc-fitted), laser-off moves only between contours that draw something — never one
// first, last or two in a row, so a contour of one point (or of zero-length pieces) leaves no
// trace. Stops with an error once the glyph holds more elements than its limit, so a hostile
// glyph costs at most the limit's worth of fitting.
#include <cstddef>
#include <string>
#include <vector>

#include "fonts/biarc.hpp"
#include "fonts/element.hpp"

namespace mark::loaders {

class OutlineContours {
 public:
  OutlineContours(double tolerance, std::size_t max_elements, std::vector<Element>& out)
      : tolerance_(tolerance), max_elements_(max_elements), out_(out) {}

  // Each returns false once the glyph has grown past its limit (nothing more is added then).
  bool move_to(const Point& p);
  bool line_to(const Point& p);
  bool curve_to(const CubicBezier& c);
  // Closes the open contour; call once after the last segment.
  bool finish();

  const Point& current() const { return current_; }
  bool over_limit() const { return over_limit_; }

 private:
  // Appends the contour's next pieces (`pieces`), first the laser-off move to the contour's start
  // if this is the first thing it draws.
  bool draw(const Element* pieces, std::size_t count);
  bool close();

  double tolerance_;
  std::size_t max_elements_;
  std::vector<Element>& out_;
  std::vector<Element> fitted_;  // one curve's arcs, before they are known to draw anything
  Point current_{0, 0};          // where the outline's pen is
  Point contour_start_{0, 0};
  Point pen_{0, 0};              // where the last drawn element ended
  bool in_contour_ = false;
  bool contour_drawn_ = false;   // the open contour has drawn at least one element
  bool drawn_ = false;           // the glyph has drawn at least one element
  bool over_limit_ = false;
};

}  // namespace mark::loaders

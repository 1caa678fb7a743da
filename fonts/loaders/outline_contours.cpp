#include "fonts/loaders/outline_contours.hpp"

#include <limits>

namespace mark::loaders {

bool OutlineContours::draw(const Element* pieces, std::size_t count) {
  if (count == 0) return true;
  if (!contour_drawn_) {
    // The move is known to be needed only now that the contour draws: a contour that draws
    // nothing never leaves a laser-off move behind.
    if (drawn_ && (contour_start_ - pen_).norm() > 0) out_.push_back(Element::line(pen_, contour_start_, false));
    contour_drawn_ = drawn_ = true;
  }
  out_.insert(out_.end(), pieces, pieces + count);
  pen_ = out_.back().end();
  if (out_.size() > max_elements_) over_limit_ = true;
  return !over_limit_;
}

bool OutlineContours::close() {
  bool ok = true;
  if (in_contour_ && (current_ - contour_start_).norm() > 0) {
    const Element closing = Element::line(current_, contour_start_);
    ok = draw(&closing, 1);
  }
  in_contour_ = contour_drawn_ = false;
  return ok;
}

bool OutlineContours::move_to(const Point& p) {
  if (!close()) return false;
  current_ = contour_start_ = p;
  in_contour_ = true;
  return true;
}

bool OutlineContours::line_to(const Point& p) {
  bool ok = true;
  if ((p - current_).norm() > 0) {
    const Element line = Element::line(current_, p);
    ok = draw(&line, 1);
  }
  current_ = p;
  return ok;
}

bool OutlineContours::curve_to(const CubicBezier& c) {
  fitted_.clear();
  current_ = c.p3;
  // The fit stops one element past what the glyph may still hold: a wild curve (up to 2^14
  // pieces deep) costs no more than the glyph's budget.
  const std::size_t left = max_elements_ - out_.size();
  const std::size_t cap = left > std::numeric_limits<std::size_t>::max() - 2 ? left : left + 2;
  if (!fit_biarcs(c, tolerance_, fitted_, cap)) {
    over_limit_ = true;
    return false;
  }
  return draw(fitted_.data(), fitted_.size());
}

bool OutlineContours::finish() { return close(); }

}  // namespace mark::loaders

#include "marker/fill/contours.hpp"

#include <sstream>
#include <string>

#include "base/error.hpp"

namespace mark {
namespace {

// Outline loaders close every loop exactly and layout only transforms it, so the ends of a loop
// agree to rounding; a gap larger than this is a real opening.
constexpr double kCloseTolerance_mm = 1e-5;
constexpr double kJoin_mm = 1e-6;

[[noreturn]] void open_stroke(std::string_view what, const Point& from, const Point& to) {
  std::ostringstream s;
  s << what << ": a stroke from (" << from.x() << ", " << from.y() << ") ends at (" << to.x()
    << ", " << to.y() << ") without closing; only closed outlines can be filled (outline fonts, "
    << "not single-line fonts)";
  throw InputError(s.str());
}

}  // namespace

std::vector<Contour> closed_contours(std::span<const Element> elements, std::string_view what) {
  std::vector<Contour> out;
  Contour current;
  const auto finish_run = [&] {
    if (current.elements.empty()) return;
    open_stroke(what, current.elements.front().start(), current.elements.back().end());
  };
  for (const Element& e : elements) {
    if (!e.laser()) {
      finish_run();
      continue;
    }
    if (e.kind() == ElementKind::line && (e.end() - e.start()).norm() <= kJoin_mm) continue;
    if (!current.elements.empty() && (current.elements.back().end() - e.start()).norm() > kJoin_mm)
      finish_run();
    current.elements.push_back(e);
    if ((e.end() - current.elements.front().start()).norm() <= kCloseTolerance_mm) {
      out.push_back(std::move(current));
      current = Contour{};
    }
  }
  finish_run();
  return out;
}

Contour rectangle_contour(const Box& b) {
  const Point p0 = b.min, p1(b.max.x(), b.min.y()), p2 = b.max, p3(b.min.x(), b.max.y());
  return Contour{{Element::line(p0, p1), Element::line(p1, p2), Element::line(p2, p3),
                  Element::line(p3, p0)}};
}

}  // namespace mark

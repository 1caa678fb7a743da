#include "test_figures.hpp"

#include <cmath>
#include <map>
#include <numbers>

#include "base/numbers.hpp"

namespace mark::test {
namespace {

// Letters at the paper's standard height 3, lower left corner at the origin.
std::vector<Element> letter(char c, double& advance) {
  std::vector<Element> e;
  advance = 2.0;
  switch (c) {
    case 'D':  // the paper's Table 2
      e.push_back(Element::line({0, 0}, {0.749, 0}));
      e.push_back(Element::arc_through({0.749, 0}, {1.6646, 0.9167}, 0.92, true));
      e.push_back(Element::line({1.6646, 0.9167}, {1.6646, 2.0835}));
      e.push_back(Element::arc_through({1.6646, 2.0835}, {0.8020, 2.9807}, 0.92, true));
      e.push_back(Element::line({0.8020, 2.9807}, {0, 3}));
      e.push_back(Element::line({0, 3}, {0, 0}));
      break;
    case 'O':  // one full circle
      e.push_back(Element::arc({1, 1.5}, 1.0, kPi / 2, 2 * kPi));
      break;
    case 'L':
      e.push_back(Element::line({0, 3}, {0, 0}));
      e.push_back(Element::line({0, 0}, {1.6, 0}));
      advance = 1.8;
      break;
    case 'T':  // two strokes with a pen move between them
      e.push_back(Element::line({0, 3}, {2, 3}));
      e.push_back(Element::line({2, 3}, {1, 3}, false));
      e.push_back(Element::line({1, 3}, {1, 0}));
      break;
    case 'S':  // two arcs turning opposite ways: an open stroke
      e.push_back(Element::arc({1, 2.25}, 0.75, 0, kPi * 1.5));
      e.push_back(Element::arc({1, 0.75}, 0.75, kPi / 2, -kPi * 1.5));
      break;
    case 'E':  // a stroke meeting another in its middle, drawn in pieces
      e.push_back(Element::line({1.6, 3}, {0, 3}));
      e.push_back(Element::line({0, 3}, {0, 1.5}));
      e.push_back(Element::line({0, 1.5}, {1.2, 1.5}));
      e.push_back(Element::line({1.2, 1.5}, {0, 1.5}, false));
      e.push_back(Element::line({0, 1.5}, {0, 0}));
      e.push_back(Element::line({0, 0}, {1.6, 0}));
      break;
    default:
      advance = 1.5;
      break;
  }
  return e;
}

}  // namespace

Figure make_figure(const FigureSpec& spec) {
  Figure fig;
  const double s = spec.height_mm / 3;
  std::string order = spec.text;
  if (spec.mirror) order.assign(spec.text.rbegin(), spec.text.rend());

  // Shaping: scale to height, shear (italic), mirror about the letter's own middle.
  std::map<char, std::size_t> shape_of;
  for (char c : order) {
    if (shape_of.count(c)) continue;
    double adv;
    std::vector<Element> src = letter(c, adv);
    Affine a = Affine::Identity();
    if (spec.mirror) {
      a.translate(Point(adv * s, 0));
      a.scale(Point(-1, 1));
    }
    Eigen::Matrix2d shear;
    shear << 1, std::tan(spec.italic_deg * kPi / 180), 0, 1;
    a = a * Affine(shear);
    a.scale(s);
    ShapedGlyph g;
    g.code_point = static_cast<char32_t>(c);
    g.advance_mm = adv * s;
    g.from_font = a;
    for (const Element& e : src) g.elements.push_back(e.transformed(a));
    shape_of[c] = fig.shapes.size();
    fig.shapes.push_back(std::move(g));
  }

  // Fitting.
  double total = 0;
  for (char c : order) total += fig.shapes[shape_of[c]].advance_mm + spec.gap_mm;
  total -= spec.gap_mm;
  double along = 0;
  for (char c : order) {
    const ShapedGlyph& sh = fig.shapes[shape_of[c]];
    PlacedGlyph p;
    p.code_point = sh.code_point;
    p.shape = shape_of[c];
    switch (spec.fit) {
      case Fit::linear:
        p.origin = spec.base + Point(along, 0);
        break;
      case Fit::inclined: {
        const double a = spec.angle_deg * kPi / 180;
        p.origin = spec.base + Point(std::cos(a), std::sin(a)) * along;
        p.rotation_rad = a;
        break;
      }
      case Fit::circular: {
        // Self-centred on top of a circle round (0, 0), reading clockwise: θs = 90° + θt/2.
        const double theta = kPi / 2 + total / spec.radius_mm / 2 - along / spec.radius_mm;
        p.origin = spec.radius_mm * Point(std::cos(theta), std::sin(theta));
        p.rotation_rad = theta - kPi / 2;
        break;
      }
    }
    for (const Element& e : sh.elements) p.elements.push_back(e.transformed(p.placement()));
    fig.glyphs.push_back(std::move(p));
    along += sh.advance_mm + spec.gap_mm;
  }
  return fig;
}

}  // namespace mark::test

#include "marker/codes/code_marks.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>

#include "base/error.hpp"
#include "base/numbers.hpp"
#include "marker/limits/code_settings.hpp"

namespace mark {
namespace {

// The modules to mark, quiet zone included: rows/cols of the extended grid, (0, 0) the top-left
// quiet-zone module (linear codes have no quiet rows).
struct MarkGrid {
  const PlacedCode& code;
  int q_rows, q_cols;  // quiet modules above/below and left/right

  int rows() const { return code.matrix.rows + 2 * q_rows; }
  int cols() const { return code.matrix.cols + 2 * q_cols; }
  bool marked(int r, int c) const {
    const int mr = r - q_rows, mc = c - q_cols;
    const bool inside = mr >= 0 && mr < code.matrix.rows && mc >= 0 && mc < code.matrix.cols;
    const bool dark = inside && code.matrix.dark(mr, mc);
    return code.layout.invert ? !dark : dark;
  }
  Box box(int r, int c) const { return code.module_box(r - q_rows, c - q_cols); }
  // The runs of marked modules along row r, left to right, each as the box it covers.
  std::vector<Box> runs(int r) const {
    std::vector<Box> out;
    for (int c = 0; c < cols();) {
      if (!marked(r, c)) {
        ++c;
        continue;
      }
      int e = c;
      while (e < cols() && marked(r, e)) ++e;
      Box run = box(r, c);
      run.add(box(r, e - 1));
      out.push_back(run);
      c = e;
    }
    return out;
  }
};

// The distance between lines that merge into one marked area: the code's first hatch set's.
double line_pitch(const PlacedCode& code) {
  const auto& sets = code.layout.fill.sets;
  return sets.empty() ? HatchSet{}.spacing_mm : sets.front().spacing_mm;
}

MarkGrid mark_grid(const PlacedCode& code) {
  // Only an inverted code marks its quiet zone.
  const int q = code.layout.invert ? code.quiet_modules : 0;
  return {code, is_linear(code.matrix.symbology) ? 0 : q, q};
}

void append(std::vector<Element>& out, const Element& e) {
  if (!out.empty() && (out.back().end() - e.start()).norm() > 0)
    out.push_back(Element::line(out.back().end(), e.start(), false));
  out.push_back(e);
}

// Square style: one run of marked modules per row becomes a rectangle; the union is hatched.
std::vector<Element> square_marks(const PlacedCode& code, FillStats& stats) {
  const MarkGrid g = mark_grid(code);
  std::vector<Contour> contours;
  for (int r = 0; r < g.rows(); ++r)
    for (const Box& run : g.runs(r)) contours.push_back(rectangle_contour(run));
  FillOptions o = code.layout.fill;
  o.origin = Point(0, 0);  // scanlines counted from the symbol's corner: the module grid
  const double m = code.module_mm;
  for (HatchSet& s : o.sets) {
    // A linear code's hatch angle counts from its bars: lines along the bars are few and long.
    if (is_linear(code.matrix.symbology)) s.angle_deg += 90;
    const double turns = s.angle_deg / 90;
    if (std::abs(turns - std::round(turns)) > 1e-9) continue;
    // Along the grid: a whole number of lines per module, the outer ones half a spacing in from
    // the module's edges (where a line of about that width burns up to the edge); the beam
    // radius pulls in the lines' ends.
    s.spacing_mm = m / std::ceil(m / s.spacing_mm - 1e-9);
    s.inset_line_ends_only = true;
  }
  Point at = code.module_box(0, 0).min;
  Filled f = fill_contours(contours, o, at);
  stats += f.stats;
  return std::move(f.elements);
}

// A spiral of semicircles about alternating centres c + (d, 0) and c, radii d, 2d, … (k−1)d,
// then the full circle of radius R = k·d: every arc exact, turns 2d ≤ pitch apart.
void spiral(std::vector<Element>& out, const Point& c, double radius, double pitch) {
  const int k = 2 * static_cast<int>(std::ceil(radius / pitch - 1e-9));
  if (k >= 2) {
    const double d = radius / k;
    const Point a = c + Point(d, 0);
    for (int j = 1; j < k; ++j) {
      const bool odd = j % 2 == 1;
      append(out, Element::arc(odd ? a : c, j * d, odd ? kPi : 0.0, kPi));
    }
  }
  append(out, Element::arc(c, radius, 0, 2 * kPi));
}

std::vector<Element> dot_marks(const PlacedCode& code, FillStats& stats) {
  const MarkGrid g = mark_grid(code);
  const double radius = code.layout.dot_share * code.module_mm / 2 - code.layout.fill.inset_mm;
  std::vector<Element> out;
  for (int r = 0; r < g.rows(); ++r)
    for (int n = 0; n < g.cols(); ++n) {
      const int c = r % 2 == 0 ? n : g.cols() - 1 - n;  // serpentine rows
      if (!g.marked(r, c)) continue;
      const Point centre = g.box(r, c).center();
      if (!out.empty()) stats.jump_length_mm += (centre - out.back().end()).norm();
      if (code.layout.dot == DotShape::spiral)
        spiral(out, centre, radius, line_pitch(code));
      else
        append(out, Element::arc(centre, radius, 0, 2 * kPi));
    }
  for (const Element& e : out)
    if (e.laser()) stats.hatch_length_mm += e.length(), ++stats.hatch_lines;
  return out;
}

// Line style: each row of marked modules (for a linear code each marked column) as lines along
// it, one stroke per run, serpentine. Across the row the lines run from a beam radius inside one
// edge to a beam radius inside the other (where a line about the beam wide burns up to the edge,
// as the runs' ends are pulled in), no farther apart than the hatch spacing: one line where the
// module is no wider than the beam (the tiny codes the style began with), nine on a 0.3 mm module.
// A single 40 µm line on a 0.12 mm module left a striped grey that no reader decoded.
std::vector<Element> line_marks(const PlacedCode& code, FillStats& stats) {
  const MarkGrid g = mark_grid(code);
  const double r = code.layout.fill.inset_mm;
  const double min_len = 0.2 * code.module_mm;  // a one-module run still marks a short dash
  const double band = code.module_mm - 2 * r;   // across a module, where line centres may lie
  const int n = band > 1e-9 ? 1 + static_cast<int>(std::ceil(band / line_pitch(code) - 1e-9)) : 1;
  std::vector<Element> out;
  // Line k of n across box b, along axis `along` (0: x, 1: y), forward or back.
  const auto add = [&](const Box& b, int along, int k, bool forward) {
    const int across = 1 - along;
    Point a = b.min, z = b.max;
    // Line k of every module the box spans across (a run is one module high, a bar one wide).
    a[across] = z[across] = n == 1 ? (b.min[across] + b.max[across]) / 2 : b.min[across] + r + k * band / (n - 1);
    if (!forward) std::swap(a, z);
    const Point mid = (a + z) / 2, dir = (z - a).normalized();
    const double half = std::max(min_len, (z - a).norm() - 2 * r) / 2;
    if (!out.empty()) stats.jump_length_mm += (mid - half * dir - out.back().end()).norm();
    append(out, Element::line(mid - half * dir, mid + half * dir));
    ++stats.hatch_lines;
    stats.hatch_length_mm += 2 * half;
  };
  bool forward = true;
  if (is_linear(code.matrix.symbology)) {
    for (int c = 0; c < g.cols(); ++c)
      if (g.marked(0, c))
        for (int k = 0; k < n; ++k, forward = !forward) add(g.box(0, c), 1, k, forward);
    return out;
  }
  // Each row is n scanlines across its runs; the scanlines run serpentine.
  for (int row = 0; row < g.rows(); ++row) {
    std::vector<Box> runs = g.runs(row);
    for (int k = 0; k < n; ++k, forward = !forward) {
      if (forward)
        for (const Box& b : runs) add(b, 0, k, true);
      else
        for (auto b = runs.rbegin(); b != runs.rend(); ++b) add(*b, 0, k, false);
    }
  }
  return out;
}

void check_layout(const CodeLayout& l, const ModuleMatrix& m) {
  check_range("code x", l.center.x(), kCodeX.range());
  check_range("code y", l.center.y(), kCodeY.range());
  check_range("code angle", l.angle_deg, kCodeAngle.range());
  if (l.module_mm != 0 && l.size_mm != 0)
    throw InputError("give the module size or the code size, not both");
  if (l.module_mm != 0) check_range("module size", l.module_mm, kModule.range());
  if (l.size_mm != 0) check_range("code size", l.size_mm, kCodeSize.range());
  if (l.bar_height_mm != 0) check_range("bar height", l.bar_height_mm, kBarHeight.range());
  check_range("dot size", l.dot_share, kDotSize.range());
  check_fill_options(l.fill);
  if (l.style == ModuleStyle::dot && is_linear(m.symbology))
    throw InputError("dot style is for 2-D codes; mark " + std::string(to_string(m.symbology)) +
                     " with square or line style");
}

}  // namespace

std::string_view to_string(ModuleStyle s) {
  return s == ModuleStyle::square ? "square" : s == ModuleStyle::dot ? "dot" : "line";
}
ModuleStyle parse_module_style(std::string_view name) {
  if (name == "square") return ModuleStyle::square;
  if (name == "dot") return ModuleStyle::dot;
  if (name == "line") return ModuleStyle::line;
  throw InputError("module style '" + std::string(name) + "' is not one of square, dot, line");
}
std::string_view to_string(DotShape s) { return s == DotShape::spiral ? "spiral" : "circle"; }
DotShape parse_dot_shape(std::string_view name) {
  if (name == "spiral") return DotShape::spiral;
  if (name == "circle") return DotShape::circle;
  throw InputError("dot shape '" + std::string(name) + "' is not one of spiral, circle");
}

Box PlacedCode::module_box(int row, int col) const {
  Box b;
  if (is_linear(matrix.symbology)) {
    b.add(Point(col * module_mm, 0));
    b.add(Point((col + 1) * module_mm, height_mm));
  } else {
    b.add(Point(col * module_mm, height_mm - (row + 1) * module_mm));
    b.add(Point((col + 1) * module_mm, height_mm - row * module_mm));
  }
  return b;
}

bool PlacedCode::keeps_clear(const Point& field) const {
  const Point p = to_field.inverse() * field;
  const double q = quiet_modules * module_mm, qy = is_linear(matrix.symbology) ? 0 : q;
  constexpr double kEdge = 1e-9;  // a mark touching the zone's edge is outside it
  return p.x() > -q + kEdge && p.x() < width_mm + q - kEdge && p.y() > -qy + kEdge && p.y() < height_mm + qy - kEdge;
}

std::optional<Point> PlacedCode::first_intrusion(const std::vector<Element>& elements) const {
  for (const Element& e : elements) {
    if (!e.laser()) continue;
    const Box b = e.bounds();
    if (b.max.x() < bounds.min.x() || b.min.x() > bounds.max.x() || b.max.y() < bounds.min.y() ||
        b.min.y() > bounds.max.y())
      continue;
    const int n = std::max(2, static_cast<int>(std::ceil(e.length() / 0.05)));
    for (int k = 0; k <= n; ++k)
      if (const Point p = e.point_at(static_cast<double>(k) / n); keeps_clear(p)) return p;
  }
  return std::nullopt;
}

PlacedCode place_code(const ModuleMatrix& matrix, const CodeLayout& layout) {
  check_layout(layout, matrix);
  PlacedCode code;
  code.matrix = matrix;
  code.layout = layout;
  code.module_mm = layout.module_mm > 0 ? layout.module_mm
                   : layout.size_mm > 0 ? layout.size_mm / matrix.cols
                                        : kDefaultModule_mm;
  check_range("module size", code.module_mm, kModule.range());
  code.quiet_modules = quiet_zone_modules(matrix.symbology);
  code.width_mm = matrix.cols * code.module_mm;
  code.height_mm = is_linear(matrix.symbology)
                       ? (layout.bar_height_mm > 0 ? layout.bar_height_mm
                                                   : std::max(0.15 * code.width_mm, 5 * code.module_mm))
                       : matrix.rows * code.module_mm;
  const double r = layout.fill.inset_mm;
  if (layout.style == ModuleStyle::square && code.module_mm <= 2 * r * 1.05)
    throw InputError("module " + std::to_string(code.module_mm) + " mm is not wider than the beam (inset " +
                     std::to_string(r) + " mm each side): square modules would vanish; use --style line or larger modules");
  if (layout.style == ModuleStyle::dot && layout.dot_share * code.module_mm / 2 - r < 0.001)
    throw InputError("module " + std::to_string(code.module_mm) + " mm is too small for dots with a beam radius of " +
                     std::to_string(r) + " mm");
  code.to_field = Affine::Identity();
  code.to_field.translate(layout.center);
  code.to_field.rotate(layout.angle_deg * kPi / 180);
  code.to_field.translate(Point(-code.width_mm / 2, -code.height_mm / 2));

  std::vector<Element> local;
  switch (layout.style) {
    case ModuleStyle::square: local = square_marks(code, code.stats); break;
    case ModuleStyle::dot: local = dot_marks(code, code.stats); break;
    case ModuleStyle::line: local = line_marks(code, code.stats); break;
  }
  code.elements.reserve(local.size());
  for (const Element& e : local) code.elements.push_back(e.transformed(code.to_field));
  const double qm = code.quiet_modules * code.module_mm;
  const double qy = is_linear(matrix.symbology) ? 0 : qm;
  for (const Point& p : {Point(-qm, -qy), Point(code.width_mm + qm, -qy), Point(-qm, code.height_mm + qy),
                         Point(code.width_mm + qm, code.height_mm + qy)})
    code.bounds.add(code.to_field * p);
  return code;
}

Figure code_figure(const PlacedCode& code) {
  Figure f;
  PlacedGlyph g;
  g.code_point = 0;
  g.elements = code.elements;
  f.glyphs.push_back(std::move(g));
  return f;
}

}  // namespace mark

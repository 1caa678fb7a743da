// Text layout after the CNC paper's data processor: scale to the requested height, apply width
// factor, font inclination (shear) and mirroring per letter, then fit the letters linearly, on an
// inclined line, or on a circle. Each distinct character is shaped once; occurrences are placed
// with a rotation and translation only, which keeps arcs circular and layout fast.
#include "marker/layout/layout.hpp"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <sstream>

#include "base/error.hpp"
#include "base/numbers.hpp"
#include "fonts/utf8.hpp"

namespace mark {
namespace {

double radians(double deg) { return deg * kPi / 180.0; }

void require_finite_positive(double v, const char* what) {
  if (!std::isfinite(v) || v <= 0) {
    std::ostringstream msg;
    msg << what << " must be a positive number, got " << v;
    throw InputError(msg.str());
  }
}

void require_finite(double v, const char* what) {
  if (!std::isfinite(v)) throw InputError(std::string(what) + " must be a finite number");
}

void validate(const LayoutOptions& o) {
  require_finite_positive(o.height_mm, "character height");
  require_finite_positive(o.width_factor, "width factor");
  require_finite_positive(o.line_spacing, "line spacing");
  require_finite(o.gap_mm, "letter gap");
  require_finite(o.base.x(), "base point x");
  require_finite(o.base.y(), "base point y");
  require_finite(o.angle_deg, "text angle");
  require_finite(o.italic_deg, "italic angle");
  if (std::abs(o.italic_deg) >= 80)
    throw InputError("italic angle must lie between -80 and 80 degrees, got " +
                     std::to_string(o.italic_deg));
  if (o.circle) {
    require_finite_positive(o.circle->radius_mm, "circle radius");
    require_finite(o.circle->center.x(), "circle centre x");
    require_finite(o.circle->center.y(), "circle centre y");
    if (o.circle->start_angle_deg) require_finite(*o.circle->start_angle_deg, "start angle");
    if (o.angle_deg != 0)
      throw InputError("a text angle cannot be combined with circular fitting; use a start angle");
  }
}

// Shapes each distinct character once and remembers its index.
class Shaper {
 public:
  Shaper(const StrokeFont& font, const LayoutOptions& o, Figure& figure)
      : font_(font), options_(o), figure_(figure) {
    const double cap = font.metrics().standard_height;
    if (!(cap > 0))
      throw InputError("font '" + font.name() + "' has no usable standard height");
    scale_x_ = o.height_mm / cap * o.width_factor;
    scale_y_ = o.height_mm / cap;
  }

  std::size_t shape(char32_t cp) {
    for (std::size_t i = 0; i < figure_.shapes.size(); ++i)
      if (figure_.shapes[i].code_point == cp) return i;
    ShapedGlyph s;
    s.code_point = cp;
    const Glyph* glyph = font_.find(cp);
    if (!glyph && cp == U' ') {
      s.advance_mm = font_.metrics().word_spacing * scale_x_;
    } else {
      if (!glyph) glyph = options_.replace_missing ? &font_.glyph_or_replacement(cp) : &font_.glyph(cp);
      s.advance_mm = glyph->advance * scale_x_;
      // Shear (font inclination) then scale: x' = sx·x + sy·tan(italic)·y, y' = sy·y.
      Eigen::Matrix2d m;
      m << scale_x_, scale_y_ * std::tan(radians(options_.italic_deg)), 0, scale_y_;
      s.from_font.linear() = m;
      s.from_font.translation().setZero();
      if (options_.mirror) {
        // Mirror the finished letter within its own advance, so a mirrored line is the exact
        // mirror image of the unmirrored one (what a die needs to print the text right-reading).
        Affine flip = Affine::Identity();
        flip.linear()(0, 0) = -1;
        flip.translation() = Point(s.advance_mm, 0);
        s.from_font = flip * s.from_font;
      }
      s.elements.reserve(glyph->elements.size());
      for (const Element& e : glyph->elements) s.elements.push_back(e.transformed(s.from_font));
    }
    figure_.shapes.push_back(std::move(s));
    return figure_.shapes.size() - 1;
  }

 private:
  const StrokeFont& font_;
  const LayoutOptions& options_;
  Figure& figure_;
  double scale_x_ = 1, scale_y_ = 1;
};

std::vector<std::u32string> split_lines(const std::u32string& text) {
  std::vector<std::u32string> lines(1);
  for (char32_t c : text) {
    if (c == U'\n') {
      lines.emplace_back();
    } else if (c != U'\r') {
      lines.back().push_back(c);
    }
  }
  return lines;
}

// Appends the glyph at `origin` / `rotation`. When the previous layout had the same shape at
// the same place at this index (`reuse`), its elements are taken over instead of being
// transformed again: a serial number that changes its last digits re-places only those.
void place(Figure& figure, std::size_t shape, std::size_t line, const Point& origin,
           double rotation, std::vector<PlacedGlyph>& reuse) {
  const std::size_t index = figure.glyphs.size();
  if (index < reuse.size()) {
    PlacedGlyph& old = reuse[index];
    if (old.shape == shape && old.line == line && old.origin == origin &&
        old.rotation_rad == rotation && old.code_point == figure.shapes[shape].code_point) {
      figure.glyphs.push_back(std::move(old));
      return;
    }
  }
  PlacedGlyph g;
  g.code_point = figure.shapes[shape].code_point;
  g.shape = shape;
  g.line = line;
  g.origin = origin;
  g.rotation_rad = rotation;
  const Affine placement = g.placement();
  const auto& local = figure.shapes[shape].elements;
  g.elements.reserve(local.size());
  for (const Element& e : local) g.elements.push_back(e.transformed(placement));
  figure.glyphs.push_back(std::move(g));
}

double line_width(const Figure& figure, const std::vector<std::size_t>& shapes, double gap) {
  double w = 0;
  for (std::size_t s : shapes) w += figure.shapes[s].advance_mm;
  if (!shapes.empty()) w += gap * static_cast<double>(shapes.size() - 1);
  return w;
}

// A negative gap may overlap letters, but every letter must still start after the one before it:
// a gap that makes a letter step backwards would mark the text out of order.
void require_forward(const Figure& figure, const std::vector<std::size_t>& shapes, double gap) {
  if (shapes.size() < 2 || gap >= 0) return;
  const std::size_t* narrowest = nullptr;
  for (std::size_t i = 0; i + 1 < shapes.size(); ++i)
    if (!narrowest || figure.shapes[shapes[i]].advance_mm < figure.shapes[*narrowest].advance_mm)
      narrowest = &shapes[i];
  const ShapedGlyph& g = figure.shapes[*narrowest];
  if (g.advance_mm + gap > 0) return;
  char msg[256];
  std::snprintf(msg, sizeof msg,
                "letter gap %g mm makes the letter after '%s' (advance %.3f mm) step backwards; "
                "the gap must be more than %.3f mm for this text",
                gap, encode_utf8(g.code_point).c_str(), g.advance_mm, -g.advance_mm);
  throw InputError(msg);
}

}  // namespace

Figure layout_text(std::string_view utf8_text, const StrokeFont& font, const LayoutOptions& o) {
  Figure figure;
  relayout_text(utf8_text, font, o, figure);
  return figure;
}

namespace {
std::atomic<std::uint64_t> layouts{0};
}  // namespace

std::uint64_t layouts_made() { return layouts.load(std::memory_order_relaxed); }

void relayout_text(std::string_view utf8_text, const StrokeFont& font, const LayoutOptions& o,
                   Figure& figure) {
  layouts.fetch_add(1, std::memory_order_relaxed);
  validate(o);
  const std::u32string text = decode_utf8(utf8_text, "text");
  std::vector<PlacedGlyph> reuse = std::move(figure.glyphs);
  figure.glyphs.clear();
  figure.glyphs.reserve(text.size());
  Shaper shaper(font, o, figure);
  figure.letter_height_mm = o.height_mm;
  const double pitch = o.line_spacing * font.metrics().line_height * o.height_mm /
                       font.metrics().standard_height;

  const std::vector<std::u32string> lines = split_lines(text);
  for (std::size_t k = 0; k < lines.size(); ++k) {
    std::vector<std::size_t> shapes;
    shapes.reserve(lines[k].size());
    for (char32_t c : lines[k]) shapes.push_back(shaper.shape(c));
    // Mirroring reverses the letter order before fitting, as the paper does.
    if (o.mirror) std::reverse(shapes.begin(), shapes.end());
    const double width = line_width(figure, shapes, o.gap_mm);
    require_forward(figure, shapes, o.gap_mm);

    if (!o.circle) {
      double x = o.base.x();
      if (o.align == Align::center) x -= width / 2;
      if (o.align == Align::right) x -= width;
      const double y = o.base.y() - static_cast<double>(k) * pitch;
      const double angle = radians(o.angle_deg);
      const Eigen::Rotation2Dd about_base(angle);
      for (std::size_t s : shapes) {
        place(figure, s, k, o.base + about_base * (Point(x, y) - o.base), angle, reuse);
        x += figure.shapes[s].advance_mm + o.gap_mm;
      }
      continue;
    }

    const CircleFit& c = *o.circle;
    // Lines below the first move toward the centre outside, away from it inside.
    const double radius = c.radius_mm + (c.inside ? 1.0 : -1.0) * static_cast<double>(k) * pitch;
    if (radius <= 0)
      throw InputError("line " + std::to_string(k + 1) + " of the text falls inside the circle's centre");
    const double total = width / radius;  // θt = S_T / R
    if (total > 2 * kPi)
      throw InputError("text line " + std::to_string(k + 1) + " is " + std::to_string(width) +
                       " mm long and does not fit on a circle of radius " + std::to_string(radius) +
                       " mm");
    // Outside the letters run clockwise from θs, inside counter-clockwise.
    const double dir = c.inside ? 1.0 : -1.0;
    const double start = c.start_angle_deg ? radians(*c.start_angle_deg)
                                            : (c.inside ? 1.5 * kPi - total / 2 : 0.5 * kPi + total / 2);
    double a = start;
    for (std::size_t s : shapes) {
      const double w = figure.shapes[s].advance_mm;
      const double centre_angle = a + dir * w / (2 * radius);
      const double rotation = centre_angle + (c.inside ? kPi / 2 : -kPi / 2);
      const Point baseline_centre =
          c.center + radius * Point(std::cos(centre_angle), std::sin(centre_angle));
      const Point origin = baseline_centre - Eigen::Rotation2Dd(rotation) * Point(w / 2, 0);
      place(figure, s, k, origin, rotation, reuse);
      a += dir * (w + o.gap_mm) / radius;  // Δθ = (W + G) / R
    }
  }
}

void require_inside(const Box& bounds, const Field& field, std::string_view what,
                    std::string_view remedy) {
  const Box f = field.box();
  if (f.contains(bounds, 1e-9)) return;
  // The side it leaves by most; a number too large for millimetres is shown in exponent form.
  const struct { double by; const char* side; } sides[] = {{f.min.x() - bounds.min.x(), "left"},
                                                          {bounds.max.x() - f.max.x(), "right"},
                                                          {f.min.y() - bounds.min.y(), "bottom"},
                                                          {bounds.max.y() - f.max.y(), "top"}};
  const auto* worst = &sides[0];
  for (const auto& s : sides)
    if (!(s.by <= worst->by)) worst = &s;
  auto mm = [](double v) {
    char buf[48];
    std::snprintf(buf, sizeof buf, std::abs(v) < 1e9 ? "%.3f" : "%.4g", v);
    return std::string(buf);
  };
  std::string msg = std::string(what) + " leaves the field by " + mm(worst->by) + " mm at the " +
                    worst->side + ": it spans x " + mm(bounds.min.x()) + " to " + mm(bounds.max.x()) +
                    " mm, y " + mm(bounds.min.y()) + " to " + mm(bounds.max.y()) + " mm; the field is " +
                    mm(field.size_mm) + " mm square (±" + mm(field.size_mm / 2) + " mm)";
  if (!remedy.empty()) msg += "; " + std::string(remedy);
  throw InputError(msg);
}

}  // namespace mark

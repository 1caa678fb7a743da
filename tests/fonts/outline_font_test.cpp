// TrueType through FreeType: DejaVu Sans loads; straight glyphs stay lines with the font's true
// heights; round glyphs are circular arcs within the tolerance of the real outline both ways
// (checked against FreeType's own decomposition, evaluated independently here); contours close;
// laser-off moves join contours; broken files are FontFileErrors naming the file.
#include <ft2build.h>
#include FT_FREETYPE_H
#include FT_OUTLINE_H
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <functional>
#include <numbers>
#include <unistd.h>

#include "fonts/catalog.hpp"
#include "fonts/error.hpp"
#include "fonts/loaders.hpp"

namespace fs = std::filesystem;

namespace mark {
namespace {

const std::string kDejaVu = "/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf";

// One piece of the true outline: a line, a quadratic or a cubic, by its control points.
struct Segment {
  std::vector<Point> p;
  Point at(double t) const {
    const double s = 1 - t;
    if (p.size() == 2) return s * p[0] + t * p[1];
    if (p.size() == 3) return s * s * p[0] + 2 * s * t * p[1] + t * t * p[2];
    return s * s * s * p[0] + 3 * s * s * t * p[1] + 3 * s * t * t * p[2] + t * t * t * p[3];
  }
  bool curved() const { return p.size() > 2; }
};

struct TrueOutline {
  std::vector<Segment> segments;
  int contours = 0;
  FT_BBox cbox{};
  double advance = 0;
  double units_per_em = 0, ascender = 0, descender = 0, height = 0;
};

// FreeType's own view of a glyph, independent of the loader under test.
TrueOutline true_outline(char32_t cp, const std::string& path = kDejaVu) {
  FT_Library lib;
  EXPECT_EQ(FT_Init_FreeType(&lib), 0);
  FT_Face face;
  EXPECT_EQ(FT_New_Face(lib, path.c_str(), 0, &face), 0);
  EXPECT_EQ(FT_Load_Glyph(face, FT_Get_Char_Index(face, cp), FT_LOAD_NO_SCALE), 0);
  TrueOutline out;
  out.contours = face->glyph->outline.n_contours;
  out.advance = face->glyph->metrics.horiAdvance;
  out.units_per_em = face->units_per_EM;
  out.ascender = face->ascender;
  out.descender = face->descender;
  out.height = face->height;
  FT_Outline_Get_CBox(&face->glyph->outline, &out.cbox);
  struct State {
    TrueOutline* o;
    Point cur;
  } st{&out, {0, 0}};
  static State* s;  // callbacks are plain function pointers
  s = &st;
  FT_Outline_Funcs f{};
  f.move_to = [](const FT_Vector* to, void*) {
    s->cur = Point(to->x, to->y);
    return 0;
  };
  f.line_to = [](const FT_Vector* to, void*) {
    s->o->segments.push_back({{s->cur, Point(to->x, to->y)}});
    s->cur = Point(to->x, to->y);
    return 0;
  };
  f.conic_to = [](const FT_Vector* c, const FT_Vector* to, void*) {
    s->o->segments.push_back({{s->cur, Point(c->x, c->y), Point(to->x, to->y)}});
    s->cur = Point(to->x, to->y);
    return 0;
  };
  f.cubic_to = [](const FT_Vector* c1, const FT_Vector* c2, const FT_Vector* to, void*) {
    s->o->segments.push_back(
        {{s->cur, Point(c1->x, c1->y), Point(c2->x, c2->y), Point(to->x, to->y)}});
    s->cur = Point(to->x, to->y);
    return 0;
  };
  EXPECT_EQ(FT_Outline_Decompose(&face->glyph->outline, &f, nullptr), 0);
  FT_Done_Face(face);
  FT_Done_FreeType(lib);
  return out;
}

const StrokeFont& dejavu() {
  static const StrokeFont font = load_outline_font(kDejaVu);
  return font;
}

double tolerance() { return kOutlineToleranceEm * true_outline(U'H').units_per_em; }

// Exact distance to a line segment or circular arc, written here independently of the library.
double distance_to(const Element& e, const Point& q) {
  if (const auto* l = std::get_if<Line>(&e.geometry())) {
    const Point d = l->end - l->start;
    const double t = std::clamp((q - l->start).dot(d) / d.squaredNorm(), 0.0, 1.0);
    return (q - (l->start + t * d)).norm();
  }
  const auto& a = std::get<CircularArc>(e.geometry());
  const Point v = q - a.center;
  // Angle of q measured from the arc's start in the arc's own direction, in [0, 2π).
  double rel = (std::atan2(v.y(), v.x()) - a.start_angle) * (a.sweep >= 0 ? 1 : -1);
  rel = std::fmod(rel, 2 * std::numbers::pi);
  if (rel < 0) rel += 2 * std::numbers::pi;
  if (rel <= std::abs(a.sweep)) return std::abs(v.norm() - a.radius);
  return std::min((q - e.start()).norm(), (q - e.end()).norm());
}

double distance_to(const Segment& s, const Point& q) {
  constexpr int n = 400;
  int k = 0;
  double best = INFINITY;
  for (int i = 0; i <= n; ++i) {
    const double d = (s.at(double(i) / n) - q).norm();
    if (d < best) best = d, k = i;
  }
  double lo = std::max(0, k - 1) / double(n), hi = std::min(n, k + 1) / double(n);
  for (int it = 0; it < 80; ++it) {  // ternary search: the distance is unimodal this close
    const double m1 = lo + (hi - lo) / 3, m2 = hi - (hi - lo) / 3;
    if ((s.at(m1) - q).norm() < (s.at(m2) - q).norm())
      hi = m2;
    else
      lo = m1;
  }
  return std::min(best, (s.at((lo + hi) / 2) - q).norm());
}

std::vector<Element> lit(const Glyph& g) {
  std::vector<Element> out;
  for (const Element& e : g.elements)
    if (e.laser()) out.push_back(e);
  return out;
}

struct BothWays {
  double fit_to_curve = 0, curve_to_fit = 0;
};


// Distance from q to the nearest segment of the outline. The segments' end points bound it from
// above, and a segment whose control-point box (which holds the whole segment) lies farther away
// cannot be nearer, so only a few segments are measured exactly.
double distance_to(const TrueOutline& truth, const Point& q) {
  double best = INFINITY;
  for (const Segment& s : truth.segments) best = std::min({best, (s.p.front() - q).norm(), (s.p.back() - q).norm()});
  for (const Segment& s : truth.segments) {
    Point lo = s.p[0], hi = s.p[0];
    for (const Point& c : s.p) lo = lo.cwiseMin(c), hi = hi.cwiseMax(c);
    const Point outside = (lo - q).cwiseMax(q - hi).cwiseMax(Point(0, 0));
    if (outside.norm() < best) best = std::min(best, distance_to(s, q));
  }
  return best;
}

// The largest distance from the fit to the true outline and from the outline (sampled `samples`
// times a segment) to the fit; `stride` > 1 measures from every stride-th element and segment
// only (the 15 000-element glyph), still against the whole of the other side.
BothWays distances_both_ways(const std::vector<Element>& fit, const TrueOutline& truth, int samples,
                             std::size_t stride = 1) {
  BothWays d;
  for (std::size_t k = 0; k < fit.size(); k += stride)
    for (int j = 0; j <= 16; ++j) d.fit_to_curve = std::max(d.fit_to_curve, distance_to(truth, fit[k].point_at(j / 16.0)));
  std::vector<Box> boxes;
  for (const Element& e : fit) boxes.push_back(e.bounds());
  for (std::size_t n = 0; n < truth.segments.size(); n += stride)
    for (int i = 0; i <= samples; ++i) {
      const Segment& s = truth.segments[n];
      const Point q = s.at(static_cast<double>(i) / samples);
      double best = INFINITY;  // the same pruning by end points and boxes as above
      for (const Element& e : fit) best = std::min({best, (e.start() - q).norm(), (e.end() - q).norm()});
      for (std::size_t k = 0; k < fit.size(); ++k) {
        const Point outside = (boxes[k].min - q).cwiseMax(q - boxes[k].max).cwiseMax(Point(0, 0));
        if (outside.norm() < best) best = std::min(best, distance_to(fit[k], q));
      }
      d.curve_to_fit = std::max(d.curve_to_fit, best);
    }
  return d;
}

TEST(OutlineFont, DejaVuSansLoadsWithTheFaceMetrics) {
  const StrokeFont& f = dejavu();
  const TrueOutline h = true_outline(U'H');
  EXPECT_GT(f.size(), 3000u);  // DejaVu Sans covers thousands of BMP code points
  EXPECT_EQ(f.name(), "DejaVuSans");
  EXPECT_EQ(f.source(), kDejaVu);
  EXPECT_EQ(f.metrics().ascender, h.ascender);
  EXPECT_EQ(f.metrics().descender, h.descender);
  EXPECT_EQ(f.metrics().line_height, h.height);
  EXPECT_EQ(f.metrics().cap_height, h.cbox.yMax);
  EXPECT_EQ(f.metrics().standard_height, f.metrics().cap_height);
  EXPECT_EQ(f.metrics().x_height, true_outline(U'x').cbox.yMax);
  EXPECT_EQ(f.glyph(U'H').advance, h.advance);
  EXPECT_EQ(f.glyph(U'g').advance, true_outline(U'g').advance);
  EXPECT_GT(f.glyph(U' ').advance, 0);
  EXPECT_TRUE(f.glyph(U' ').elements.empty());
}

TEST(OutlineFont, StraightGlyphIsLinesWithTheTrueCapHeight) {
  const Glyph& g = dejavu().glyph(U'H');
  const TrueOutline h = true_outline(U'H');
  ASSERT_FALSE(g.elements.empty());
  for (const Element& e : g.elements) EXPECT_EQ(e.kind(), ElementKind::line);
  EXPECT_EQ(h.cbox.yMax, 1493);  // DejaVu Sans: 2048 units per em, capitals 1493 high
  const Box b = g.bounds();
  EXPECT_EQ(b.max.y(), h.cbox.yMax);
  EXPECT_EQ(b.min.y(), h.cbox.yMin);
  EXPECT_EQ(b.min.x(), h.cbox.xMin);
  EXPECT_EQ(b.max.x(), h.cbox.xMax);
  EXPECT_EQ(lit(g).size(), h.segments.size());  // one line per outline line, none zero-length
}

TEST(OutlineFont, RoundGlyphIsArcsWithinToleranceOfTheTrueOutlineBothWays) {
  const double tol = tolerance();
  for (const char32_t cp : {U'O', U'o', U'e', U'S', U'g'}) {
    const TrueOutline truth = true_outline(cp);
    const std::vector<Element> fit = lit(dejavu().glyph(cp));
    std::size_t lines = 0;
    for (const Element& e : fit) lines += e.kind() == ElementKind::line;
    std::size_t true_lines = 0;
    for (const Segment& s : truth.segments) true_lines += !s.curved();
    if (cp == U'O') {
      EXPECT_EQ(true_lines, 0u);
      EXPECT_EQ(lines, 0u) << "'O' must be circular arcs only";
    }
    const auto [fit_to_curve, curve_to_fit] = distances_both_ways(fit, truth, 300);
    EXPECT_LE(fit_to_curve, tol + 1e-9) << describe_code_point(cp);
    EXPECT_LE(curve_to_fit, tol + 1e-9) << describe_code_point(cp);
  }
}

// CFF (cubic) outlines, a small TrueType and the 2000-point hostile glyph: the fit stays within
// the tolerance of FreeType's own outline both ways.
TEST(OutlineFont, CffTrueTypeAndTheHostileGlyphFitWithinToleranceBothWays) {
  const std::string dir = std::string(MARKER_SOURCE_DIR) + "/tests/fonts/data/outline/";
  for (const auto& [file, cp] : {std::pair{"sample_cff.otf", U'O'}, {"sample_cff.otf", U'H'}, {"sample.ttf", U'O'},
                                 {"blob_1.ttf", U'A'}}) {
    const std::size_t stride = std::string(file) == "blob_1.ttf" ? 101 : 1;
    const std::string path = dir + file;
    const StrokeFont f = load_outline_font(path);
    const TrueOutline truth = true_outline(cp, path);
    const double tol = kOutlineToleranceEm * truth.units_per_em;
    const auto [fit_to_curve, curve_to_fit] = distances_both_ways(lit(f.glyph(cp)), truth, 60, stride);
    EXPECT_LE(fit_to_curve, tol + 1e-9) << file;
    EXPECT_LE(curve_to_fit, tol + 1e-9) << file;
    if (std::string(file) == "sample_cff.otf") {
      const bool cubic = std::any_of(truth.segments.begin(), truth.segments.end(),
                                     [](const Segment& s) { return s.p.size() == 4; });
      EXPECT_EQ(cubic, cp == U'O') << "CFF outlines are cubics";
    }
  }
}

TEST(OutlineFont, ContoursAreClosedAndJoinedByLaserOffMoves) {
  for (const char32_t cp : {U'O', U'A', U'g', U'8', U'%', U'@', U'B', U'i'}) {
    const Glyph& g = dejavu().glyph(cp);
    const TrueOutline truth = true_outline(cp);
    ASSERT_FALSE(g.elements.empty());
    int contours = 1;
    std::size_t contour_start = 0;
    EXPECT_TRUE(g.elements.front().laser());
    EXPECT_TRUE(g.elements.back().laser());
    for (std::size_t i = 0; i < g.elements.size(); ++i) {
      const Element& e = g.elements[i];
      if (i > 0) {
        EXPECT_LT((e.start() - g.elements[i - 1].end()).norm(), 1e-6)
            << describe_code_point(cp) << " element " << i << " does not start where the last ended";
      }
      const bool contour_ends = i + 1 == g.elements.size() || !g.elements[i + 1].laser();
      if (e.laser() && contour_ends) {
        EXPECT_LT((e.end() - g.elements[contour_start].start()).norm(), 1e-6)
            << describe_code_point(cp) << " contour " << contours << " is open";
      }
      if (!e.laser()) {
        ++contours;
        contour_start = i + 1;
        EXPECT_TRUE(g.elements[i - 1].laser());
        EXPECT_EQ(e.kind(), ElementKind::line);
      }
    }
    EXPECT_EQ(contours, truth.contours) << describe_code_point(cp);
  }
}

void write_file(const fs::path& p, const std::string& bytes) {
  std::ofstream(p, std::ios::binary) << bytes;
}

void expect_font_error_naming(const std::string& path) {
  for (int via = 0; via < 3; ++via) {
    try {
      if (via == 0) load_outline_font(path);
      if (via == 1) load_font_file(path);
      if (via == 2) open_font(path);
      ADD_FAILURE() << path << " loaded";
    } catch (const FontFileError& e) {
      EXPECT_NE(std::string(e.what()).find(path), std::string::npos) << e.what();
    }
  }
}

TEST(OutlineFont, BrokenFilesAreFontFileErrorsNamingTheFile) {
  const fs::path dir = fs::temp_directory_path() / ("outline_font_test_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  std::ifstream in(kDejaVu, std::ios::binary);
  std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  ASSERT_GT(bytes.size(), 1000u);
  write_file(dir / "truncated.ttf", bytes.substr(0, 1000));
  write_file(dir / "text.ttf", "this is not a font\n");
  write_file(dir / "empty.otf", "");
  expect_font_error_naming((dir / "truncated.ttf").string());
  expect_font_error_naming((dir / "text.ttf").string());
  expect_font_error_naming((dir / "empty.otf").string());
  try {
    load_outline_font((dir / "missing.ttf").string());
    ADD_FAILURE() << "a missing file loaded";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()), "cannot read font file '" + (dir / "missing.ttf").string() + "': No such file or directory");
  }
  fs::remove_all(dir);
}

TEST(OutlineFont, InstalledFontsListTrueTypeAndOpenByName) {
  bool found = false;
  for (const FontFile& f : installed_fonts())
    if (f.path == kDejaVu) found = f.format == "ttf" && f.name == "DejaVuSans";
  EXPECT_TRUE(found);
  const auto font = open_font("DejaVuSans");
  EXPECT_EQ(font->source(), kDejaVu);
  EXPECT_EQ(font->metrics().cap_height, 1493);
}

// The reason for arcs: the same accuracy takes far fewer elements than chords.
TEST(OutlineFont, ArcsAreFewerThanChordsAtTheSameTolerance) {
  const double tol = tolerance();
  std::size_t arcs = 0, chords = 0;
  for (const char32_t cp : std::u32string(U"Ag0123456789SOQ&@")) {
    for (const Element& e : lit(dejavu().glyph(cp))) arcs += e.kind() == ElementKind::arc;
    for (const Segment& s : true_outline(cp).segments) {
      if (!s.curved()) continue;
      // Adaptive chords: halve until every sampled point is within tol of its chord.
      std::function<std::size_t(double, double)> count = [&](double t0, double t1) -> std::size_t {
        const Point a = s.at(t0), b = s.at(t1);
        double worst = 0;
        for (int i = 1; i < 16; ++i) {
          const Point q = s.at(t0 + (t1 - t0) * i / 16);
          const Point d = b - a;
          const double u = std::clamp((q - a).dot(d) / d.squaredNorm(), 0.0, 1.0);
          worst = std::max(worst, (q - (a + u * d)).norm());
        }
        if (worst <= tol) return 1;
        return count(t0, (t0 + t1) / 2) + count((t0 + t1) / 2, t1);
      };
      chords += count(0, 1);
    }
  }
  RecordProperty("arcs", static_cast<int>(arcs));
  RecordProperty("chords", static_cast<int>(chords));
  std::printf("sample text: %zu arcs vs %zu chords at %.4g font units\n", arcs, chords, tol);
  EXPECT_LT(arcs * 2, chords);
}

}  // namespace
}  // namespace mark

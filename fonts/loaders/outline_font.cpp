// TrueType / OpenType outline fonts through FreeType: every contour of every glyph becomes a
// closed lit stroke of lines and circular arcs (Béziers biarc-fitted), in font units, baseline 0,
// y up — the same elements the stroke-font loaders produce, so layout, hatching and the machines
// need nothing new.
#include <ft2build.h>
#include FT_FREETYPE_H
#include FT_OUTLINE_H
#include FT_TRUETYPE_TABLES_H

#include <cstdio>
#include <filesystem>
#include <memory>

#include "fonts/biarc.hpp"
#include "fonts/error.hpp"
#include "fonts/loaders.hpp"

namespace mark {
namespace {

// Code points above the Basic Multilingual Plane (emoji, historic scripts) are left out: marking
// text lives in the BMP and loading them would only cost time.
constexpr char32_t kLastCodePoint = 0xFFFF;

std::string freetype_message(FT_Error error) {
  if (const char* s = FT_Error_String(error)) return s;
  char buf[32];
  std::snprintf(buf, sizeof buf, "FreeType error 0x%02X", static_cast<unsigned>(error));
  return buf;
}

struct LibraryDeleter {
  void operator()(FT_Library l) const { FT_Done_FreeType(l); }
};
struct FaceDeleter {
  void operator()(FT_Face f) const { FT_Done_Face(f); }
};

// Collects one glyph's contours from FT_Outline_Decompose.
struct ContourBuilder {
  double tolerance;
  std::vector<Element>* out;
  Point current{0, 0};
  Point contour_start{0, 0};
  bool in_contour = false;
  bool has_contour = false;

  void close() {
    if (in_contour && (current - contour_start).norm() > 0)
      out->push_back(Element::line(current, contour_start));
    in_contour = false;
  }
  void move_to(const Point& p) {
    close();
    // Laser off from the end of the previous contour to the start of this one.
    if (has_contour && (p - current).norm() > 0) out->push_back(Element::line(current, p, false));
    current = contour_start = p;
    in_contour = has_contour = true;
  }
  void line_to(const Point& p) {
    if ((p - current).norm() > 0) out->push_back(Element::line(current, p));
    current = p;
  }
  void curve_to(const CubicBezier& c) {
    fit_biarcs(c, tolerance, *out);
    current = c.p3;
  }
};

Point to_point(const FT_Vector* v) { return {static_cast<double>(v->x), static_cast<double>(v->y)}; }
ContourBuilder& builder(void* user) { return *static_cast<ContourBuilder*>(user); }

int on_move(const FT_Vector* to, void* user) {
  builder(user).move_to(to_point(to));
  return 0;
}
int on_line(const FT_Vector* to, void* user) {
  builder(user).line_to(to_point(to));
  return 0;
}
int on_conic(const FT_Vector* control, const FT_Vector* to, void* user) {
  ContourBuilder& b = builder(user);
  b.curve_to(CubicBezier::from_quadratic(b.current, to_point(control), to_point(to)));
  return 0;
}
int on_cubic(const FT_Vector* c1, const FT_Vector* c2, const FT_Vector* to, void* user) {
  ContourBuilder& b = builder(user);
  b.curve_to(CubicBezier{b.current, to_point(c1), to_point(c2), to_point(to)});
  return 0;
}

const FT_Outline_Funcs kOutlineFuncs = {on_move, on_line, on_conic, on_cubic, 0, 0};

}  // namespace

StrokeFont load_outline_font(const std::string& path, Warnings* /*warnings*/,
                             double tolerance_em) {
  const auto fail = [&](const std::string& what) { throw FontFileError(path, 0, what); };
  FT_Library raw_library = nullptr;
  if (FT_Error e = FT_Init_FreeType(&raw_library))
    fail("cannot start FreeType: " + freetype_message(e));
  std::unique_ptr<FT_LibraryRec_, LibraryDeleter> library(raw_library);

  FT_Face raw_face = nullptr;
  if (FT_Error e = FT_New_Face(library.get(), path.c_str(), 0, &raw_face))
    fail("not a font FreeType can read: " + freetype_message(e));
  std::unique_ptr<FT_FaceRec_, FaceDeleter> face(raw_face);
  if (!FT_IS_SCALABLE(face.get())) fail("not an outline font (bitmap only)");
  if (FT_Select_Charmap(face.get(), FT_ENCODING_UNICODE) != 0)
    fail("has no Unicode character map");
  if (face->units_per_EM == 0) fail("has no units per em");

  FontMetrics metrics;
  metrics.ascender = face->ascender;
  metrics.descender = face->descender;
  metrics.line_height = face->height;
  StrokeFont font(std::filesystem::path(path).stem().string(), path, metrics);

  ContourBuilder contours{tolerance_em * face->units_per_EM, nullptr};
  FT_UInt index = 0;
  for (FT_ULong code = FT_Get_First_Char(face.get(), &index); index != 0 && code <= kLastCodePoint;
       code = FT_Get_Next_Char(face.get(), code, &index)) {
    const std::string where = "glyph for " + describe_code_point(static_cast<char32_t>(code));
    if (FT_Error e = FT_Load_Glyph(face.get(), index, FT_LOAD_NO_SCALE))
      fail(where + ": " + freetype_message(e));
    const FT_GlyphSlot slot = face->glyph;
    Glyph glyph;
    glyph.code_point = static_cast<char32_t>(code);
    glyph.advance = static_cast<double>(slot->metrics.horiAdvance);
    if (slot->format != FT_GLYPH_FORMAT_OUTLINE) fail(where + ": not an outline");
    contours = ContourBuilder{contours.tolerance, &glyph.elements};
    if (FT_Error e = FT_Outline_Decompose(&slot->outline, &kOutlineFuncs, &contours))
      fail(where + ": " + freetype_message(e));
    contours.close();
    font.add(std::move(glyph));
  }

  // Heights from the glyphs themselves (what a user measures on the mark), else the OS/2 table.
  const auto* os2 = static_cast<const TT_OS2*>(FT_Get_Sfnt_Table(face.get(), FT_SFNT_OS2));
  const auto top_of = [&](char32_t cp, double fallback) {
    const Glyph* g = font.find(cp);
    const Box b = g ? g->bounds() : Box{};
    return b.empty() ? fallback : b.max.y();
  };
  FontMetrics& m = font.metrics();
  m.cap_height = top_of(U'H', os2 && os2->sCapHeight > 0 ? os2->sCapHeight : face->ascender);
  m.x_height = top_of(U'x', os2 && os2->sxHeight > 0 ? os2->sxHeight : m.cap_height * 0.7);
  m.standard_height = m.cap_height;
  const Glyph* space = font.find(U' ');
  m.word_spacing = space ? space->advance : face->units_per_EM / 4.0;
  return font;
}

}  // namespace mark

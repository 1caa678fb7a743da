#include "fonts/loaders/outline_glyphs.hpp"

#include FT_OUTLINE_H

#include <cstdio>

#include "fonts/error.hpp"
#include "fonts/loaders/outline_contours.hpp"

namespace mark::loaders {
namespace {

// Code points above the Basic Multilingual Plane (emoji, historic scripts) are left out: marking
// text lives in the BMP, and it bounds a character map's walk to 65 536 steps.
constexpr char32_t kLastCodePoint = 0xFFFF;

// FreeType's own error texts, from the table in FT_ERRORS_H (FreeType's documented way to list
// them: Debian's FreeType is built without FT_Error_String's strings).
#undef FTERRORS_H_
#define FT_ERROR_START_LIST {
#define FT_ERRORDEF(e, v, s) {v, s},
#define FT_ERROR_END_LIST {0, nullptr}};
const struct {
  int code;
  const char* text;
} kFreeTypeErrors[] =
#include FT_ERRORS_H

std::string freetype_message(FT_Error error) {
  if (const char* s = FT_Error_String(error)) return s;
  for (const auto& e : kFreeTypeErrors)
    if (e.text && e.code == error) return e.text;
  char buf[32];
  std::snprintf(buf, sizeof buf, "FreeType error 0x%02X", static_cast<unsigned>(error));
  return buf;
}

// FreeType's decomposition callbacks; a non-zero return stops the walk (the glyph is over its limit).
constexpr int kStop = 1;
Point to_point(const FT_Vector* v) { return {static_cast<double>(v->x), static_cast<double>(v->y)}; }
OutlineContours& contours(void* user) { return *static_cast<OutlineContours*>(user); }

int on_move(const FT_Vector* to, void* user) { return contours(user).move_to(to_point(to)) ? 0 : kStop; }
int on_line(const FT_Vector* to, void* user) { return contours(user).line_to(to_point(to)) ? 0 : kStop; }
int on_conic(const FT_Vector* control, const FT_Vector* to, void* user) {
  OutlineContours& c = contours(user);
  return c.curve_to(CubicBezier::from_quadratic(c.current(), to_point(control), to_point(to))) ? 0 : kStop;
}
int on_cubic(const FT_Vector* c1, const FT_Vector* c2, const FT_Vector* to, void* user) {
  OutlineContours& c = contours(user);
  return c.curve_to(CubicBezier{c.current(), to_point(c1), to_point(c2), to_point(to)}) ? 0 : kStop;
}
const FT_Outline_Funcs kOutlineFuncs = {on_move, on_line, on_conic, on_cubic, 0, 0};

}  // namespace

OutlineGlyphs::OutlineGlyphs(std::string bytes, std::string source, double tolerance_em, OutlineLimits limits)
    : bytes_(std::move(bytes)), source_(std::move(source)), limits_(limits) {
  if (FT_Error e = FT_Init_FreeType(&library_)) fail("cannot start FreeType: " + freetype_message(e));
  if (FT_Error e = FT_New_Memory_Face(library_, reinterpret_cast<const FT_Byte*>(bytes_.data()),
                                      static_cast<FT_Long>(bytes_.size()), 0, &face_)) {
    face_ = nullptr;
    FT_Done_FreeType(library_);
    fail("not a font FreeType can read: " + freetype_message(e));
  }
  const auto refuse = [&](const std::string& what) {
    FT_Done_Face(face_);
    FT_Done_FreeType(library_);
    fail(what);
  };
  if (!FT_IS_SCALABLE(face_)) refuse("not an outline font (bitmap only)");
  if (FT_Select_Charmap(face_, FT_ENCODING_UNICODE) != 0) refuse("has no Unicode character map");
  if (face_->units_per_EM == 0) refuse("has no units per em");
  tolerance_ = tolerance_em * face_->units_per_EM;
  for_each_code_point([&](char32_t) { ++code_point_count_; });
}

template <class Visit>
void OutlineGlyphs::for_each_code_point(Visit visit) const {
  FT_UInt index = 0;
  for (FT_ULong code = FT_Get_First_Char(face_, &index); index != 0 && code <= kLastCodePoint;
       code = FT_Get_Next_Char(face_, code, &index))
    // A malformed map (format 4 segments out of order) can walk to codes its lookup does not
    // find: only what find() finds is listed.
    if (FT_Get_Char_Index(face_, code) != 0) visit(static_cast<char32_t>(code));
}

OutlineGlyphs::~OutlineGlyphs() {
  FT_Done_Face(face_);
  FT_Done_FreeType(library_);
}

void OutlineGlyphs::fail(const std::string& what) const { throw FontFileError(source_, 0, what); }

std::vector<char32_t> OutlineGlyphs::code_points() const {
  std::lock_guard lock(mutex_);
  std::vector<char32_t> out;
  out.reserve(code_point_count_);
  for_each_code_point([&](char32_t cp) { out.push_back(cp); });
  return out;
}

std::size_t OutlineGlyphs::glyphs_made() const {
  std::lock_guard lock(mutex_);
  return made_.size();
}

const Glyph* OutlineGlyphs::find(char32_t code_point) const {
  if (code_point > kLastCodePoint) return nullptr;
  std::lock_guard lock(mutex_);
  const FT_UInt index = FT_Get_Char_Index(face_, code_point);
  if (index == 0) return nullptr;
  const Made& m = make(index, code_point);
  if (!m.glyph) fail(m.refusal);
  return m.glyph.get();
}

const OutlineGlyphs::Made& OutlineGlyphs::make(FT_UInt index, char32_t code_point) const {
  if (auto it = made_.find(index); it != made_.end()) return it->second;
  Made& made = made_[index];
  const std::string where = "glyph for " + describe_code_point(code_point);
  if (FT_Error e = FT_Load_Glyph(face_, index, FT_LOAD_NO_SCALE)) {
    made.refusal = where + ": " + freetype_message(e);
    return made;
  }
  const FT_GlyphSlot slot = face_->glyph;
  if (slot->format != FT_GLYPH_FORMAT_OUTLINE) {
    made.refusal = where + ": not an outline";
    return made;
  }
  auto glyph = std::make_unique<Glyph>();
  // Filed under the first code point that asked for it; every code point mapped to this glyph
  // index gets this same glyph.
  glyph->code_point = code_point;
  glyph->advance = static_cast<double>(slot->metrics.horiAdvance);
  OutlineContours contours(tolerance_, limits_.glyph_elements, glyph->elements);
  const FT_Error e = FT_Outline_Decompose(&slot->outline, &kOutlineFuncs, &contours);
  if (contours.over_limit() || !contours.finish()) {
    made.refusal = where + ": more than " + std::to_string(limits_.glyph_elements) +
                   " elements, the limit for one glyph";
    return made;
  }
  if (e) {
    made.refusal = where + ": " + freetype_message(e);
    return made;
  }
  if (elements_held_ + glyph->elements.size() > limits_.font_elements) {
    made.refusal = where + ": " + std::to_string(glyph->elements.size()) + " elements would make the font hold " +
                   std::to_string(elements_held_ + glyph->elements.size()) + ", more than its limit of " +
                   std::to_string(limits_.font_elements);
    return made;
  }
  glyph->elements.shrink_to_fit();
  elements_held_ += glyph->elements.size();
  made.glyph = std::move(glyph);
  return made;
}

}  // namespace mark::loaders

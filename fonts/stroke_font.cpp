#include "fonts/stroke_font.hpp"

#include <algorithm>
#include <cstdio>

#include "fonts/error.hpp"
#include "fonts/utf8.hpp"

namespace mark {

std::string describe_code_point(char32_t cp) {
  char hex[16];
  std::snprintf(hex, sizeof hex, "U+%04X", static_cast<unsigned>(cp));
  if (cp < 0x20 || cp == 0x7F) return hex;
  // Built with append: GCC 12 warns falsely (-Wrestrict) on "'" + std::string.
  std::string s(1, '\'');
  s.append(encode_utf8(cp)).append("' (").append(hex).append(")");
  return s;
}

void StrokeFont::add(Glyph glyph) {
  const char32_t cp = glyph.code_point;
  glyphs_.insert_or_assign(cp, std::move(glyph));
}

std::size_t StrokeFont::size() const {
  if (!lazy_) return glyphs_.size();
  return glyphs_.empty() ? lazy_->code_point_count() : code_points().size();
}

std::vector<char32_t> StrokeFont::code_points() const {
  std::vector<char32_t> out;
  for (const auto& [cp, g] : glyphs_) out.push_back(cp);
  if (lazy_) {
    const std::vector<char32_t> more = lazy_->code_points();
    out.insert(out.end(), more.begin(), more.end());
    std::sort(out.begin(), out.end());
    out.erase(std::unique(out.begin(), out.end()), out.end());
  }
  return out;
}

const Glyph* StrokeFont::find(char32_t cp) const {
  auto it = glyphs_.find(cp);
  if (it != glyphs_.end()) return &it->second;
  return lazy_ ? lazy_->find(cp) : nullptr;
}

const Glyph& StrokeFont::glyph(char32_t cp) const {
  if (const Glyph* g = find(cp)) return *g;
  throw MissingGlyphError("font '" + name_ + "' has no glyph for " + describe_code_point(cp));
}

const Glyph& StrokeFont::glyph_or_replacement(char32_t cp) const {
  if (const Glyph* g = find(cp)) return *g;
  if (const Glyph* g = find(replacement_)) return *g;
  throw MissingGlyphError("font '" + name_ + "' has no glyph for " + describe_code_point(cp) +
                          " and no replacement glyph " + describe_code_point(replacement_));
}

}  // namespace mark

#pragma once
// The glyphs of an outline font, made on first use (GlyphSource): FreeType reads the font from
// its bytes in memory; a glyph is decomposed and biarc-fitted the first time a text asks for one
// of its characters and kept per glyph index, so any number of code points mapped to one outline
// cost one fit. Two limits bound what a hostile font can cost: elements per glyph and elements
// held by the whole font; a glyph over either is refused (and stays refused) naming the file, the
// character and the limit.
//
// Thread-safety: one mutex guards the FreeType face and the cache. FreeType faces are not safe
// to share between threads, and find() fills the cache from a const method, so every call takes
// the lock; glyphs are never moved or changed once made, so the pointers handed out need none.
#include <ft2build.h>
#include FT_FREETYPE_H

#include <map>
#include <memory>
#include <mutex>
#include <string>

#include "fonts/glyph_source.hpp"
#include "fonts/loaders.hpp"

namespace mark::loaders {

class OutlineGlyphs final : public GlyphSource {
 public:
  // `bytes`: the font file's contents; `source`: how messages name it. Throws FontFileError when
  // FreeType cannot read the font or it has no Unicode character map.
  OutlineGlyphs(std::string bytes, std::string source, double tolerance_em, OutlineLimits limits);
  ~OutlineGlyphs() override;
  OutlineGlyphs(const OutlineGlyphs&) = delete;
  OutlineGlyphs& operator=(const OutlineGlyphs&) = delete;

  const Glyph* find(char32_t code_point) const override;
  std::size_t code_point_count() const override { return code_point_count_; }
  std::vector<char32_t> code_points() const override;

  // What the metrics are read from (no glyph is made).
  FT_Face face() const { return face_; }
  // How many glyphs have been made (or refused) so far: one per glyph index asked for.
  std::size_t glyphs_made() const;

 private:
  struct Made {
    std::unique_ptr<Glyph> glyph;  // null: refused, `refusal` says why
    std::string refusal;
  };
  const Made& make(FT_UInt index, char32_t code_point) const;  // with the lock held
  template <class Visit>
  void for_each_code_point(Visit visit) const;  // with the lock held (or from the constructor)
  [[noreturn]] void fail(const std::string& what) const;

  std::string bytes_;  // FreeType reads the font from here for the face's lifetime
  std::string source_;
  double tolerance_;   // font units
  OutlineLimits limits_;
  FT_Library library_ = nullptr;
  FT_Face face_ = nullptr;
  std::size_t code_point_count_ = 0;

  mutable std::mutex mutex_;
  mutable std::map<FT_UInt, Made> made_;
  mutable std::size_t elements_held_ = 0;
};

}  // namespace mark::loaders

#pragma once
// A stroke font: metrics plus glyphs looked up by Unicode code point. A stroke-font file's glyphs
// are all held (they are small and already strokes); an outline font's are made on first use by
// its GlyphSource.
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "fonts/glyph.hpp"
#include "fonts/glyph_source.hpp"

namespace mark {

struct FontMetrics {
  double cap_height = 0;       // height of capital letters above the baseline (font units)
  double x_height = 0;         // height of lower-case letters without ascenders
  double ascender = 0;         // highest point of the font above the baseline
  double descender = 0;        // lowest point below the baseline (negative)
  double baseline = 0;         // where the source file put the baseline, in its own coordinates
  double standard_height = 0;  // the height that a requested character height maps to
  double line_height = 0;      // baseline-to-baseline distance at line spacing 1
  double letter_spacing = 0;   // extra advance between letters the font asks for
  double word_spacing = 0;     // advance of a space where the font has no space glyph
};

class StrokeFont {
 public:
  StrokeFont() = default;
  StrokeFont(std::string name, std::string source, FontMetrics metrics)
      : name_(std::move(name)), source_(std::move(source)), metrics_(metrics) {}
  // A font whose glyphs come from `glyphs` as they are asked for (copies share the source).
  StrokeFont(std::string name, std::string source, FontMetrics metrics, std::shared_ptr<const GlyphSource> glyphs)
      : name_(std::move(name)), source_(std::move(source)), metrics_(metrics), lazy_(std::move(glyphs)) {}

  const std::string& name() const { return name_; }
  // Where the font came from: "built-in" or the file's path.
  const std::string& source() const { return source_; }
  const FontMetrics& metrics() const { return metrics_; }
  FontMetrics& metrics() { return metrics_; }

  void add(Glyph glyph);
  // How many code points have a glyph (an outline font: how many its character map maps).
  std::size_t size() const;
  // Every code point with a glyph, ascending; makes no glyph.
  std::vector<char32_t> code_points() const;
  // The glyphs held in memory: all of a stroke-font file's, none of an outline font's (use
  // code_points() and find() to visit those).
  const std::map<char32_t, Glyph>& glyphs() const { return glyphs_; }

  // Makes the glyph on first use for an outline font (see GlyphSource::find, which may throw
  // FontFileError); safe to call from several threads on a font nobody add()s to.
  const Glyph* find(char32_t code_point) const;
  // Throws MissingGlyphError naming the character and the font.
  const Glyph& glyph(char32_t code_point) const;
  // The glyph, or the replacement glyph ('?' unless set) when the font lacks it; throws only if
  // the replacement is missing too.
  const Glyph& glyph_or_replacement(char32_t code_point) const;
  void set_replacement(char32_t code_point) { replacement_ = code_point; }

 private:
  std::string name_;
  std::string source_;
  FontMetrics metrics_;
  std::map<char32_t, Glyph> glyphs_;
  std::shared_ptr<const GlyphSource> lazy_;
  char32_t replacement_ = U'?';
};

// "'A' (U+0041)": how messages name a character.
std::string describe_code_point(char32_t code_point);

}  // namespace mark

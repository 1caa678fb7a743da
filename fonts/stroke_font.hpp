#pragma once
// A stroke font: metrics plus glyphs looked up by Unicode code point.
#include <map>
#include <optional>
#include <string>

#include "fonts/glyph.hpp"

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

  const std::string& name() const { return name_; }
  // Where the font came from: "built-in" or the file's path.
  const std::string& source() const { return source_; }
  const FontMetrics& metrics() const { return metrics_; }
  FontMetrics& metrics() { return metrics_; }

  void add(Glyph glyph);
  std::size_t size() const { return glyphs_.size(); }
  const std::map<char32_t, Glyph>& glyphs() const { return glyphs_; }

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
  char32_t replacement_ = U'?';
};

// "'A' (U+0041)": how messages name a character.
std::string describe_code_point(char32_t code_point);

}  // namespace mark

#pragma once
// The last step every loader shares: raw glyphs → strokes → a StrokeFont with measured metrics.
#include <optional>
#include <string>
#include <vector>

#include "fonts/loaders/raw_glyph.hpp"
#include "fonts/stroke_font.hpp"

namespace mark::loaders {

struct FontFormat {
  // Cap height to fall back on when the font has no 'H' or 'I' with height (21 Hershey, 9 LFF/CXF).
  double nominal_cap_height = 0;
  // Hershey glyphs carry their advance even when empty (the space); LFF/CXF glyphs without
  // elements are dropped, as LibreCAD and QCAD do, so a space falls back on the word spacing.
  bool keep_empty_glyphs = false;
  // LibreCAD/QCAD: a glyph advances by its rightmost point plus the font's letter spacing (this
  // value). Unset: the parser set each RawGlyph::advance itself (Hershey bearings).
  std::optional<double> advance_after_right_edge;
};

// Assembles each glyph's strokes (joining ends that meet within the shared fraction of the
// letter height, fonts/stroke_join.hpp, taken of nominal_cap_height),
// adds the glyphs, and measures the metrics the file does not state: cap height from 'H' (else
// 'I'), x-height from 'x' (else the cap height), ascender and descender over all glyphs;
// standard_height = cap_height. `metrics` brings what the parser knows (baseline, line height,
// spacing). Throws FontFileError at `end_line` if no glyph is left. The font's name is the stem
// of `source`.
StrokeFont build_font(const std::string& source, FontMetrics metrics, std::vector<RawGlyph> glyphs,
                      const FontFormat& format, std::size_t end_line);

}  // namespace mark::loaders

#pragma once
// Letter and word spacing the way F-Engrave (and QCAD before it) sets them, for users who come
// from there: a letter advances by the right edge of its drawing plus the character spacing, a
// space by the word spacing — both given in % of the character (cap) height, so they keep
// their proportion at every size. F-Engrave states its percentages of the font's widest glyph;
// the height is what a user measures on the part and the same for every font.
#include <optional>

#include "fonts/stroke_font.hpp"

namespace mark {

// A copy of `font` with the given spacing; an unset value keeps the font's own. Glyphs without a
// drawing other than the space keep their advance.
StrokeFont respaced_font(const StrokeFont& font, std::optional<double> char_spacing_pct,
                         std::optional<double> word_spacing_pct);

}  // namespace mark

#pragma once
// Dot characters placed in the field, by the same text layout as stroke characters.
#include <string_view>

#include "fonts/stroke_font.hpp"
#include "marker/layout/layout.hpp"
#include "marker/peen/dot_font.hpp"
#include "marker/peen/dot_text.hpp"

namespace mark {

// A dot-matrix text: each character's matrix is laid out as a glyph (height = distance between
// the centres of its top and bottom rows, advance = columns + 1) and each dot is mapped through
// that glyph's placement. The dot pitch is height / (rows − 1). Errors as layout_text.
DotText layout_dot_text(std::string_view utf8_text, const DotFont& font,
                        const LayoutOptions& options);

// "Continuous" dot characters from any stroke figure: each glyph's lit elements are chained into
// strokes by the shared join rule (fonts/stroke_join.hpp), each stroke is cut at its corners (a
// turn of more than 10° between elements), and every smooth run gets evenly spaced dots at most
// `pitch_mm` apart, both ends included — so a corner is always struck and a curve drawn in
// pieces is not. Then every dot closer than half a pitch to one already kept is dropped, so
// joints and crossings are struck once. Cells are positions in each glyph's
// own frame on a grid of the pitch. Throws InputError for a pitch that is not positive.
DotText dots_along_strokes(const Figure& figure, double pitch_mm);

}  // namespace mark

#include "marker/layout/respace.hpp"

namespace mark {

StrokeFont respaced_font(const StrokeFont& font, std::optional<double> char_pct, std::optional<double> word_pct) {
  StrokeFont out(font.name(), font.source(), font.metrics());
  const double height = font.metrics().standard_height;
  if (word_pct) out.metrics().word_spacing = *word_pct / 100 * height;
  for (const auto& [cp, g] : font.glyphs()) {
    Glyph copy = g;
    const Box b = g.bounds();
    if (cp == U' ') {
      if (word_pct) copy.advance = *word_pct / 100 * height;
    } else if (char_pct && !b.empty()) {
      copy.advance = b.max.x() + *char_pct / 100 * height;
    }
    out.add(std::move(copy));
  }
  return out;
}

}  // namespace mark

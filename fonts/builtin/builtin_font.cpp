// TEMPORARY placeholder until the built-in font lands.
#include "fonts/catalog.hpp"
namespace mark {
const StrokeFont& builtin_font() {
  static const StrokeFont font("builtin", "built-in", FontMetrics{});
  return font;
}
}  // namespace mark

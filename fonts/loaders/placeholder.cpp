// TEMPORARY placeholder until the loaders land.
#include "fonts/error.hpp"
#include "fonts/loaders.hpp"
namespace mark {
StrokeFont parse_jhf(std::string_view, const std::string& s, Warnings*) { throw InputError(s + ": jhf not yet"); }
StrokeFont parse_lff(std::string_view, const std::string& s, Warnings*) { throw InputError(s + ": lff not yet"); }
StrokeFont parse_cxf(std::string_view, const std::string& s, Warnings*) { throw InputError(s + ": cxf not yet"); }
StrokeFont load_font_file(const std::string& s, Warnings* w) {
  if (s.ends_with(".ttf") || s.ends_with(".otf") || s.ends_with(".TTF") || s.ends_with(".OTF")) return load_outline_font(s, w);
  throw InputError(s + ": not yet");
}
}  // namespace mark

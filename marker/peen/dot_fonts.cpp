#include "marker/peen/dot_fonts.hpp"

namespace mark {

const DotFont* find_dot_font(std::string_view name) {
  if (name == "5x7") return &dot_font_5x7();
  if (name == "7x9") return &dot_font_7x9();
  if (name == "10x16") return &dot_font_10x16();
  return nullptr;
}

std::vector<std::string_view> dot_font_names() { return {"5x7", "7x9", "10x16"}; }

}  // namespace mark

#include "marker/peen/dot_font.hpp"

#include "fonts/error.hpp"
#include "fonts/stroke_font.hpp"

namespace mark {

DotFont::DotFont(std::string name, int columns, int rows)
    : name_(std::move(name)), columns_(columns), rows_(rows) {
  if (columns < 1 || rows < 2)
    throw InputError("dot font '" + name_ + "': a matrix needs at least 1 column and 2 rows, got " +
                     std::to_string(columns) + "x" + std::to_string(rows));
}

void DotFont::add(char32_t code_point, std::initializer_list<std::string_view> bitmap) {
  const std::string where = "dot font '" + name_ + "', glyph " + describe_code_point(code_point);
  if (static_cast<int>(bitmap.size()) != rows_)
    throw InputError(where + ": " + std::to_string(bitmap.size()) + " rows, the matrix has " +
                     std::to_string(rows_));
  DotGlyph glyph{code_point, {}};
  int row = 0;
  for (std::string_view line : bitmap) {
    if (static_cast<int>(line.size()) != columns_)
      throw InputError(where + ", row " + std::to_string(row) + ": " +
                       std::to_string(line.size()) + " columns, the matrix has " +
                       std::to_string(columns_));
    for (int col = 0; col < columns_; ++col) {
      const char c = line[static_cast<std::size_t>(col)];
      if (c == '#')
        glyph.dots.push_back({col, row});
      else if (c != '.')
        throw InputError(where + ", row " + std::to_string(row) + ", column " +
                         std::to_string(col) + ": '" + std::string(1, c) +
                         "' is neither '#' nor '.'");
    }
    ++row;
  }
  glyphs_.insert_or_assign(code_point, std::move(glyph));
}

const DotGlyph* DotFont::find(char32_t code_point) const {
  auto it = glyphs_.find(code_point);
  return it == glyphs_.end() ? nullptr : &it->second;
}

const DotGlyph& DotFont::glyph(char32_t code_point) const {
  if (const DotGlyph* g = find(code_point)) return *g;
  throw MissingGlyphError("dot font '" + name_ + "' has no glyph for " +
                          describe_code_point(code_point));
}

}  // namespace mark

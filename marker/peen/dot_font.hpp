#pragma once
// Dot-matrix fonts for pin (dot-peen) marking: every character is a fixed grid of dot positions,
// some of them struck. Glyphs are drawn in code as rows of strings ('#' a dot, '.' none) so a
// reader can see each character.
#include <initializer_list>
#include <map>
#include <string>
#include <string_view>
#include <vector>

namespace mark {

// A cell of a character's dot matrix: column from the left, row from the top (the matrix origin
// is the top-left corner, where the patent's planner starts its search).
struct DotCell {
  int col = 0;
  int row = 0;
  bool operator==(const DotCell&) const = default;
};

struct DotGlyph {
  char32_t code_point = 0;
  std::vector<DotCell> dots;  // row by row from the top, left to right within a row
};

class DotFont {
 public:
  DotFont(std::string name, int columns, int rows);

  const std::string& name() const { return name_; }
  int columns() const { return columns_; }
  int rows() const { return rows_; }
  const std::map<char32_t, DotGlyph>& glyphs() const { return glyphs_; }

  // Adds a glyph drawn as exactly rows() strings of columns() characters each, '#' for a dot and
  // '.' for an empty cell. Throws InputError naming the font, the character and the row when the
  // drawing has the wrong size or another character.
  void add(char32_t code_point, std::initializer_list<std::string_view> bitmap);

  const DotGlyph* find(char32_t code_point) const;
  // Throws MissingGlyphError naming the character and the font.
  const DotGlyph& glyph(char32_t code_point) const;

 private:
  std::string name_;
  int columns_;
  int rows_;
  std::map<char32_t, DotGlyph> glyphs_;
};

}  // namespace mark

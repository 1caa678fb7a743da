#pragma once
// Where fonts come from: the built-in marking font, and the stroke-font files installed on the
// machine (Debian's hershey-fonts-data, librecad-data, QCAD fonts, TrueType/OpenType under
// /usr/share/fonts), opened by name or by path.
#include <memory>
#include <string>
#include <vector>

#include "fonts/loaders.hpp"
#include "fonts/stroke_font.hpp"

namespace mark {

// Our own single-stroke marking font, compiled into the library. The default of every command.
const StrokeFont& builtin_font();
inline constexpr const char* kBuiltinFontName = "builtin";

struct FontFile {
  std::string name;    // file stem, e.g. "rowmans"
  std::string format;  // "jhf", "lff", "cxf", "ttf", "otf"
  std::string path;
};

// The directories searched for font files, in order.
std::vector<std::string> font_directories();
// Every font file found in those directories, sorted by name.
std::vector<FontFile> installed_fonts();

// Whether `name` (a file stem) names exactly one of `fonts`.
bool font_name_is_unique(const std::string& name, const std::vector<FontFile>& fonts);

// "builtin", a path to a font file, or the name of an installed font ("rowmans", "standard",
// "rowmans.jhf"). Throws InputError naming the font when nothing matches, and when the name
// matches several files (cursive.jhf and cursive.lff): the message lists them, and the name
// with its extension or the path picks one. Never picks one silently.
std::shared_ptr<const StrokeFont> open_font(const std::string& name_or_path,
                                            Warnings* warnings = nullptr);

}  // namespace mark

// Reading a font file from disk and choosing its parser by extension.
#include <algorithm>
#include <cctype>
#include <filesystem>

#include "base/error.hpp"
#include "fonts/loaders.hpp"
#include "fonts/loaders/read_font_file.hpp"

namespace fs = std::filesystem;

namespace mark {

StrokeFont load_font_file(const std::string& path, Warnings* warnings) {
  std::string ext = fs::path(path).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  // Outline fonts are read by FreeType from the file itself.
  if (ext == ".ttf" || ext == ".otf") return load_outline_font(path, warnings);
  using Parser = StrokeFont (*)(std::string_view, const std::string&, Warnings*);
  Parser parse = nullptr;
  if (ext == ".jhf")
    parse = parse_jhf;
  else if (ext == ".lff")
    parse = parse_lff;
  else if (ext == ".cxf")
    parse = parse_cxf;
  else
    throw InputError(
        "font file '" + path + "' has " +
        (ext.empty() ? std::string("no extension") : "an unknown extension '" + ext + "'") +
        " (expected .jhf, .lff, .cxf, .ttf or .otf)");
  const std::string text = loaders::read_font_file(path);
  // The parsers name the font after the stem of the source they are given.
  return parse(text, path, warnings);
}

}  // namespace mark

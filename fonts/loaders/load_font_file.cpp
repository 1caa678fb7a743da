// Reading a font file from disk and choosing its parser by extension.
#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>

#include "base/error.hpp"
#include "fonts/loaders.hpp"

namespace fs = std::filesystem;

namespace mark {
namespace {

// The largest font we know (LibreCAD's amiri-regular.lff) is 7.4 MB.
constexpr std::uintmax_t kMaxFontFileBytes = 64u << 20;

std::string read_font_file(const std::string& path) {
  const auto fail = [&](const std::string& why) {
    throw InputError("cannot read font file '" + path + "': " + why);
  };
  std::error_code ec;
  const fs::file_status status = fs::status(path, ec);
  if (ec || !fs::exists(status)) fail(ec ? ec.message() : "no such file");
  if (fs::is_directory(status)) fail("it is a directory");
  if (!fs::is_regular_file(status)) fail("not a regular file");
  const std::uintmax_t size = fs::file_size(path, ec);
  if (ec) fail(ec.message());
  if (size > kMaxFontFileBytes) fail("larger than 64 MiB, not a stroke font");

  std::ifstream in(path, std::ios::binary);
  if (!in) fail(std::strerror(errno));
  std::string text(static_cast<std::size_t>(size), '\0');
  in.read(text.data(), static_cast<std::streamsize>(size));
  if (in.gcount() != static_cast<std::streamsize>(size)) fail("read error");
  return text;
}

}  // namespace

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
  const std::string text = read_font_file(path);
  // The parsers name the font after the stem of the source they are given.
  return parse(text, path, warnings);
}

}  // namespace mark

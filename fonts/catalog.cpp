#include "fonts/catalog.hpp"

#include <algorithm>
#include <cstdlib>
#include <filesystem>

#include "base/error.hpp"

namespace fs = std::filesystem;

namespace mark {

std::vector<std::string> font_directories() {
  std::vector<std::string> dirs;
  // MARKER_FONT_PATH lets a user add directories (colon-separated) before the system ones.
  if (const char* extra = std::getenv("MARKER_FONT_PATH")) {
    std::string s = extra;
    std::size_t start = 0;
    while (start <= s.size()) {
      const std::size_t end = std::min(s.find(':', start), s.size());
      if (end > start) dirs.push_back(s.substr(start, end - start));
      start = end + 1;
    }
  }
  for (const char* d : {"/usr/share/hershey-fonts", "/usr/share/librecad/fonts",
                        "/usr/share/qcad/fonts", "/usr/share/fonts"})
    dirs.emplace_back(d);
  return dirs;
}

std::vector<FontFile> installed_fonts() {
  std::vector<FontFile> out;
  for (const std::string& dir : font_directories()) {
    std::error_code ec;
    if (!fs::is_directory(dir, ec)) continue;
    // Recursive: /usr/share/fonts keeps TrueType/OpenType files in per-package subdirectories.
    for (const auto& entry :
         fs::recursive_directory_iterator(dir, fs::directory_options::skip_permission_denied, ec)) {
      std::string ext = entry.path().extension().string();
      std::transform(ext.begin(), ext.end(), ext.begin(), ::tolower);
      if (ext == ".jhf" || ext == ".lff" || ext == ".cxf" || ext == ".ttf" || ext == ".otf")
        out.push_back({entry.path().stem().string(), ext.substr(1), entry.path().string()});
    }
  }
  std::stable_sort(out.begin(), out.end(), [](const FontFile& a, const FontFile& b) {
    return a.name < b.name;
  });
  return out;
}

bool font_name_is_unique(const std::string& name, const std::vector<FontFile>& fonts) {
  return std::count_if(fonts.begin(), fonts.end(), [&](const FontFile& f) { return f.name == name; }) == 1;
}

std::shared_ptr<const StrokeFont> open_font(const std::string& name, Warnings* warnings) {
  if (name == kBuiltinFontName || name.empty())
    return std::shared_ptr<const StrokeFont>(&builtin_font(), [](const StrokeFont*) {});
  std::error_code ec;
  if (fs::is_regular_file(name, ec)) return std::make_shared<StrokeFont>(load_font_file(name, warnings));
  const fs::path wanted(name);
  std::vector<FontFile> matches;
  for (const FontFile& f : installed_fonts())
    if (f.name == name || fs::path(f.path).filename() == wanted) matches.push_back(f);
  if (matches.size() == 1) return std::make_shared<StrokeFont>(load_font_file(matches.front().path, warnings));
  if (matches.size() > 1) {
    std::sort(matches.begin(), matches.end(), [](const FontFile& a, const FontFile& b) { return a.path < b.path; });
    std::string which;
    for (const FontFile& f : matches) which += (which.empty() ? "" : ", ") + f.path;
    const bool same_file_name = fs::path(matches[0].path).filename() == fs::path(matches[1].path).filename();
    throw InputError("font '" + name + "' matches " + std::to_string(matches.size()) + " installed files (" +
                     which + "); " +
                     (same_file_name ? "give the path of the one to use"
                                     : "name it with its extension (" + name + "." + matches[0].format +
                                           ") or give its path"));
  }
  throw InputError("unknown font '" + name +
                   "': not 'builtin', not a font file, and not an installed font (see 'marker fonts')");
}

}  // namespace mark

#pragma once
// Files the G-code tests write and read back: a fresh path in a folder of the build tree, and a
// whole file as text.
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

namespace mark::test {

// `name` in build/<folder>/, with any file of that name from an earlier run removed.
inline std::string cnc_out_path(const std::string& folder, const std::string& name) {
  const std::filesystem::path dir = std::filesystem::path(MARKER_BINARY_DIR) / folder;
  std::filesystem::create_directories(dir);
  std::filesystem::remove(dir / name);
  return (dir / name).string();
}

inline std::string slurp(const std::string& path) {
  std::ifstream in(path);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

}  // namespace mark::test

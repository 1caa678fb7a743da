// load_font_file: reading from disk, choosing the parser by extension, naming the font.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "fonts/loaders.hpp"
#include "loader_test_util.hpp"

namespace fs = std::filesystem;

namespace mark {
namespace {

// A scratch directory removed at the end of the test.
struct TempDir {
  fs::path path = fs::temp_directory_path() /
                  ("marker_load_font_file_" +
                   std::to_string(::testing::UnitTest::GetInstance()->random_seed()) + "_" +
                   ::testing::UnitTest::GetInstance()->current_test_info()->name());
  TempDir() { fs::create_directories(path); }
  ~TempDir() { fs::remove_all(path); }
};

void expect_input_error(const std::string& path, std::string_view fragment) {
  try {
    load_font_file(path);
    ADD_FAILURE() << "no error for " << path;
  } catch (const FontFileError& e) {
    ADD_FAILURE() << "FontFileError for an unreadable file: " << e.what();
  } catch (const InputError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("'" + path + "'"), std::string::npos) << what;
    EXPECT_NE(what.find(fragment), std::string::npos) << what << "\n  expected: " << fragment;
  }
}

TEST(LoadFontFile, NamesTheFontAfterTheFileStem) {
  const std::string path = test::kDataDir + "/sample.lff";
  const StrokeFont f = load_font_file(path);
  EXPECT_EQ(f.name(), "sample");
  EXPECT_EQ(f.source(), path);
  EXPECT_EQ(f.size(), 7u);
  EXPECT_EQ(load_font_file(test::kDataDir + "/rowmans_wrapped.jhf").name(), "rowmans_wrapped");
}

TEST(LoadFontFile, ExtensionIsCaseInsensitive) {
  TempDir dir;
  const fs::path copy = dir.path / "Sample.CXF";
  fs::copy_file(test::kDataDir + "/sample.cxf", copy);
  const StrokeFont f = load_font_file(copy.string());
  EXPECT_EQ(f.name(), "Sample");
  EXPECT_EQ(f.size(), 10u);
}

TEST(LoadFontFile, ParserErrorsNameThePath) {
  TempDir dir;
  const fs::path bad = dir.path / "bad.lff";
  std::ofstream(bad) << "[0041] A\n0,0;1,1\n\n[0042] B\nC0099\n";
  test::expect_font_error([&] { load_font_file(bad.string()); }, bad.string(), 5, "no glyph");
}

TEST(LoadFontFile, UnreadableFilesAreInputErrors) {
  TempDir dir;
  expect_input_error((dir.path / "missing.jhf").string(), "No such file or directory");
  const fs::path folder = dir.path / "folder.lff";
  fs::create_directory(folder);
  expect_input_error(folder.string(), "is a directory");
  expect_input_error("/dev/null.jhf", "No such file or directory");
  const fs::path unknown = dir.path / "font.shx";
  std::ofstream(unknown) << "x";
  expect_input_error(unknown.string(),
                     "unknown extension '.shx' (expected .jhf, .lff, .cxf, .ttf or .otf)");
  const fs::path bare = dir.path / "font";
  std::ofstream(bare) << "x";
  expect_input_error(bare.string(), "no extension");
}

TEST(LoadFontFile, RefusesSpecialFiles) {
  // A character device named like a font must not be read forever.
  std::error_code ec;
  if (!fs::exists("/dev/zero", ec)) GTEST_SKIP();
  TempDir dir;
  const fs::path link = dir.path / "zero.jhf";
  fs::create_symlink("/dev/zero", link);
  expect_input_error(link.string(), "not a regular file");
}

}  // namespace
}  // namespace mark

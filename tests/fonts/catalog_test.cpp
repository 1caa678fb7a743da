// Fonts by name: a name several installed files share is never resolved silently — the error lists
// the files and says how to pick one — while the name with its extension, or the path, opens it.
#include "fonts/catalog.hpp"

#include <gtest/gtest.h>
#include <stdlib.h>

#include <filesystem>

#include "base/error.hpp"
#include "loader_test_util.hpp"

namespace mark {
namespace {

namespace fs = std::filesystem;

// A font directory holding twin.jhf and twin.lff (two different fonts, one name), searched first.
class TwinFonts : public testing::Test {
 protected:
  void SetUp() override {
    // A folder per test: CTest runs this suite's two tests at once, in two processes.
    dir_ = fs::temp_directory_path() / "marker_catalog_test" /
           testing::UnitTest::GetInstance()->current_test_info()->name();
    fs::remove_all(dir_);
    fs::create_directories(dir_);
    fs::copy_file(test::kDataDir + "/rowmans_wrapped.jhf", dir_ / "twin.jhf");
    fs::copy_file(test::kDataDir + "/sample.lff", dir_ / "twin.lff");
    const char* old = std::getenv("MARKER_FONT_PATH");
    had_ = old != nullptr;
    if (had_) old_ = old;
    setenv("MARKER_FONT_PATH", dir_.c_str(), 1);
  }
  void TearDown() override {
    if (had_) setenv("MARKER_FONT_PATH", old_.c_str(), 1);
    else unsetenv("MARKER_FONT_PATH");
    fs::remove_all(dir_);
  }
  fs::path dir_;
  bool had_ = false;
  std::string old_;
};

TEST_F(TwinFonts, SharedNameIsRefusedWithTheFiles) {
  const std::vector<FontFile> fonts = installed_fonts();
  EXPECT_FALSE(font_name_is_unique("twin", fonts));
  try {
    open_font("twin");
    FAIL() << "an ambiguous name was resolved";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()), "font 'twin' matches 2 installed files (" + (dir_ / "twin.jhf").string() +
                                         ", " + (dir_ / "twin.lff").string() +
                                         "); name it with its extension (twin.jhf) or give its path");
  }
}

TEST_F(TwinFonts, ExtensionOrPathPicksOne) {
  const auto jhf = open_font("twin.jhf");
  const auto lff = open_font("twin.lff");
  const auto by_path = open_font((dir_ / "twin.lff").string());
  EXPECT_NE(jhf->size(), lff->size()) << "two different fonts";
  EXPECT_EQ(lff->size(), by_path->size());
  EXPECT_TRUE(font_name_is_unique("rowmans", installed_fonts()) || !fs::exists("/usr/share/hershey-fonts/rowmans.jhf"));
}

}  // namespace
}  // namespace mark

// The output-file helper: a path is checked before any work (the error names the file and the
// system's reason), and a file is written whole or not at all — a write that fails half-way
// leaves the old file as it was and no temporary file behind.
#include "marker/output/output_file.hpp"

#include <gtest/gtest.h>
#include <sys/resource.h>
#include <sys/stat.h>

#include <csignal>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "../cli_runner.hpp"
#include "base/error.hpp"

namespace mark {
namespace {

namespace fs = std::filesystem;

// A folder of the running test's own (CTest runs these tests in parallel processes).
fs::path fresh_dir() {
  return test::fresh_temp_dir(std::string("marker_output_file_test_") +
                              testing::UnitTest::GetInstance()->current_test_info()->name());
}

std::string slurp(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

std::string error_of(auto&& f) {
  try {
    f();
  } catch (const InputError& e) {
    return e.what();
  }
  return "(no error)";
}

std::size_t entries(const fs::path& dir) {
  return static_cast<std::size_t>(std::distance(fs::directory_iterator(dir), fs::directory_iterator()));
}

TEST(OutputFile, WritesTheBytesAndReplacesAnOldFile) {
  const fs::path dir = fresh_dir(), file = dir / "a.bin";
  std::string bytes(100000, '\0');
  for (std::size_t i = 0; i < bytes.size(); ++i) bytes[i] = static_cast<char>(i * 7);
  write_file_whole(file.string(), bytes);
  EXPECT_EQ(slurp(file), bytes);
  write_file_whole(file.string(), "second");
  EXPECT_EQ(slurp(file), "second");
  EXPECT_EQ(entries(dir), 1u) << "no temporary file left";
  // A new file gets the usual permissions (0666 less the umask), not a temporary file's 0600.
  const mode_t mask = ::umask(0);
  ::umask(mask);
  EXPECT_EQ(fs::status(file).permissions(), static_cast<fs::perms>(0666 & ~mask));
}

TEST(OutputFile, AFailedWriteLeavesTheOldFileAndNoTemporary) {
  const fs::path dir = fresh_dir(), file = dir / "plan.csv";
  write_file_whole(file.string(), "old contents\n");
  // Files may grow to 4 kB only: the write of 64 kB fails part-way (EFBIG), as on a full disk.
  std::signal(SIGXFSZ, SIG_IGN);
  rlimit old{};
  ASSERT_EQ(getrlimit(RLIMIT_FSIZE, &old), 0);
  rlimit small = old;
  small.rlim_cur = 4096;
  ASSERT_EQ(setrlimit(RLIMIT_FSIZE, &small), 0);
  const std::string message = error_of([&] { write_file_whole(file.string(), std::string(65536, 'x')); });
  setrlimit(RLIMIT_FSIZE, &old);
  std::signal(SIGXFSZ, SIG_DFL);
  EXPECT_EQ(message, "output file '" + file.string() + "': cannot write: File too large");
  EXPECT_EQ(slurp(file), "old contents\n");
  EXPECT_EQ(entries(dir), 1u);
}

TEST(OutputFile, MissingDirectoryIsNamedWithTheSystemsReason) {
  EXPECT_EQ(error_of([] { write_file_whole("/nonexistent-dir/x.ngc", "G0"); }),
            "output file '/nonexistent-dir/x.ngc': cannot create a file in '/nonexistent-dir': No such file or "
            "directory");
}

TEST(OutputFile, PathsAreCheckedWithoutLeavingAnything) {
  const fs::path dir = fresh_dir();
  EXPECT_NO_THROW(check_output_path("--output", (dir / "x.PNG").string(), {".svg", ".png"}));
  EXPECT_NO_THROW(check_output_path("--output", "relative-name.ngc"));
  EXPECT_EQ(entries(dir), 0u) << "the check's probe file is removed";
  EXPECT_FALSE(fs::exists("relative-name.ngc"));
  EXPECT_EQ(error_of([&] { check_output_path("--preview", (dir / "x.jpg").string(), {".svg", ".png"}); }),
            "--preview '" + (dir / "x.jpg").string() + "': the name must end in .svg or .png");
  EXPECT_EQ(error_of([&] { check_output_path("-o", dir.string()); }), "-o '" + dir.string() + "': is a directory");
  EXPECT_EQ(error_of([] { check_output_path("-o", "/etc/hostname/x"); }),
            "-o '/etc/hostname/x': '/etc/hostname' is not a directory");
  EXPECT_EQ(error_of([] { check_output_path("-o", ""); }), "-o: the file name is empty");
}

TEST(OutputFile, LowerExtension) {
  EXPECT_EQ(lower_extension("a/b.C.PNG"), ".png");
  EXPECT_EQ(lower_extension("dir.d/file"), "");
}

}  // namespace
}  // namespace mark

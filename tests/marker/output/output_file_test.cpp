// The output-file helper: a path is checked before any work (the error names the file and the
// system's reason), and a file is written whole or not at all — a write that fails half-way
// leaves the old file as it was and no temporary file behind.
#include "marker/output/output_file.hpp"

#include <gtest/gtest.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <sys/types.h>

#include <csignal>
#include <filesystem>
#include <fstream>
#include <iostream>
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

// A link is written through: its target gets the bytes (atomically, as any file), the link stays
// a link — through a chain of links, relative and absolute, and to a target not there yet.
TEST(OutputFile, WritesThroughSymbolicLinksToTheirTarget) {
  const fs::path dir = fresh_dir();
  fs::create_directories(dir / "real");
  write_file_whole((dir / "real/plan.ngc").string(), "old");
  fs::create_symlink("real/plan.ngc", dir / "link.ngc");        // relative to the link's folder
  fs::create_symlink(dir / "link.ngc", dir / "link2.ngc");      // absolute, to a link
  EXPECT_NO_THROW(check_output_path("-o", (dir / "link2.ngc").string(), {".ngc"}));
  write_file_whole((dir / "link2.ngc").string(), "G0 X1\n");
  EXPECT_TRUE(fs::is_symlink(dir / "link.ngc"));
  EXPECT_TRUE(fs::is_symlink(dir / "link2.ngc"));
  EXPECT_EQ(slurp(dir / "real/plan.ngc"), "G0 X1\n");
  EXPECT_EQ(entries(dir / "real"), 1u) << "no temporary file left beside the target";
  EXPECT_EQ(entries(dir), 3u);
  // A dangling link: its target is created.
  fs::create_symlink("real/new.svg", dir / "new.svg");
  write_file_whole((dir / "new.svg").string(), "<svg/>");
  EXPECT_TRUE(fs::is_symlink(dir / "new.svg"));
  EXPECT_EQ(slurp(dir / "real/new.svg"), "<svg/>");
  // A loop is named, not followed for ever.
  fs::create_symlink("loop-b", dir / "loop-a");
  fs::create_symlink("loop-a", dir / "loop-b");
  EXPECT_EQ(error_of([&] { write_file_whole((dir / "loop-a").string(), "x"); }),
            "output file '" + (dir / "loop-a").string() + "': too many levels of symbolic links");
}

// A FIFO or a device node is refused, named, before any work; the node stays what it was.
TEST(OutputFile, RefusesFifosAndDevices) {
  const fs::path dir = fresh_dir(), fifo = dir / "pipe.ngc";
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  const std::string why = ", not a regular file: give a file name, or - for standard output";
  EXPECT_EQ(error_of([&] { check_output_path("--output", fifo.string()); }),
            "--output '" + fifo.string() + "': is a named pipe (FIFO)" + why);
  EXPECT_EQ(error_of([&] { write_file_whole(fifo.string(), "G0"); }),
            "output file '" + fifo.string() + "': is a named pipe (FIFO)" + why);
  EXPECT_TRUE(fs::is_fifo(fifo));
  for (const char* device : {"/dev/null", "/dev/full"}) {
    EXPECT_EQ(error_of([&] { check_output_path("--preview", device); }),
              std::string("--preview '") + device + "': is a device" + why);
    EXPECT_EQ(error_of([&] { write_file_whole(device, "x"); }), std::string("output file '") + device + "': is a device" + why);
    EXPECT_TRUE(fs::is_character_file(device));
  }
  // Through a link to a device too.
  fs::create_symlink("/dev/null", dir / "null.csv");
  EXPECT_EQ(error_of([&] { check_output_path("-o", (dir / "null.csv").string()); }),
            "-o '" + (dir / "null.csv").string() + "': is a device" + why);
  EXPECT_EQ(entries(dir), 2u);
}

// "-" is standard output: the bytes go there whole, and while a command has claimed it for a
// file, what else it prints goes to standard error.
TEST(OutputFile, DashIsStandardOutput) {
  testing::internal::CaptureStdout();
  testing::internal::CaptureStderr();
  std::string error;
  try {
    check_output_path("--output", "-", {".svg", ".png"});  // no extension needed
    std::cout << "a report line\n";
    write_file_whole("-", std::string("<svg>\0</svg>", 12));
  } catch (const InputError& e) {
    error = e.what();
  }
  release_standard_output();
  const std::string out = testing::internal::GetCapturedStdout();
  const std::string err = testing::internal::GetCapturedStderr();
  EXPECT_EQ(error, "");
  EXPECT_EQ(out, std::string("<svg>\0</svg>", 12));
  EXPECT_EQ(err, "a report line\n");
  EXPECT_EQ(output_format("-", {".svg", ".png"}), ".svg");
  EXPECT_EQ(output_format("a.PNG", {".svg", ".png"}), ".png");
}

TEST(OutputFile, LowerExtension) {
  EXPECT_EQ(lower_extension("a/b.C.PNG"), ".png");
  EXPECT_EQ(lower_extension("dir.d/file"), "");
}

}  // namespace
}  // namespace mark

// Ctrl-C and progress for the long commands (console_progress.hpp): the real binary gets SIGINT
// while it works — gcode (a protrusion plate that takes minutes), peen (a long needle path) and
// preview (a long text) — and must exit 130 with one line saying where it stopped and that
// nothing was written, leaving no file (nor a temporary one) behind. Work that runs for over a
// second prints where it is on stderr, unless --quiet. (How fast it stops is a figure of
// docs/cnc.md, measured by scripts, not asserted here: tests assert no wall-clock times.)
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <csignal>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include "tests/marker/cli_runner.hpp"

namespace mark::test {
namespace {

namespace fs = std::filesystem;

struct Stopped {
  bool exited = false;
  int code = -1;
  std::string err;
};

// Runs the marker binary with `args`, sends SIGINT after `after`, returns how it ended.
Stopped interrupt_after(const std::vector<std::string>& args, std::chrono::milliseconds after, const fs::path& err_file) {
  const std::string binary = std::string(MARKER_BINARY_DIR) + "/marker/marker";
  const pid_t pid = fork();
  if (pid == 0) {
    if (!freopen(err_file.c_str(), "w", stderr) || !freopen("/dev/null", "w", stdout)) _exit(99);
    std::vector<char*> argv{const_cast<char*>(binary.c_str())};
    for (const std::string& a : args) argv.push_back(const_cast<char*>(a.c_str()));
    argv.push_back(nullptr);
    execv(binary.c_str(), argv.data());
    _exit(98);
  }
  Stopped s;
  if (pid < 0) return s;
  std::this_thread::sleep_for(after);
  kill(pid, SIGINT);
  int status = 0;
  if (waitpid(pid, &status, 0) != pid) return s;
  s.exited = WIFEXITED(status);
  s.code = s.exited ? WEXITSTATUS(status) : -1;
  std::ifstream in(err_file);
  std::ostringstream text;
  text << in.rdbuf();
  s.err = text.str();
  return s;
}

std::string rows(const std::string& line, int n) {
  std::string t;
  for (int k = 0; k < n; ++k) t += (k ? "\\n" : "") + line;
  return t;
}

// Nothing in the folder: no output and no temporary file.
void expect_empty(const fs::path& dir) {
  for (const auto& entry : fs::directory_iterator(dir)) ADD_FAILURE() << "left behind: " << entry.path();
}

TEST(Interrupt, GcodeStopsWithNothingWrittenAndSaysWhere) {
  const fs::path dir = fresh_temp_dir("marker_interrupt_gcode");
  const fs::path errors = fresh_temp_dir("marker_interrupt_gcode_err") / "stderr.txt";
  // 40 rows of raised letters: minutes of Clipper work; stopped after a second and a half, by
  // which time it has said where it is.
  const Stopped s = interrupt_after({"gcode", rows("The quick brown fox jumps over the lazy dog", 40), "--mode",
                                     "protrusion", "--height", "5", "--tool-diameter", "0.5", "-o",
                                     (dir / "plate.ngc").string()},
                                    std::chrono::milliseconds(1500), errors);
  ASSERT_TRUE(s.exited) << "killed by the signal instead of stopping";
  EXPECT_EQ(s.code, 130);
  EXPECT_NE(s.err.find("marker: interrupted while "), std::string::npos) << s.err;
  EXPECT_NE(s.err.find("; nothing was written\n"), std::string::npos) << s.err;
  // After a second of work, a progress line: "marker: TASK: N … (1 s)".
  EXPECT_NE(s.err.find(" s)\n"), std::string::npos) << s.err;
  expect_empty(dir);
}

TEST(Interrupt, QuietGcodePrintsOnlyWhereItStopped) {
  const fs::path dir = fresh_temp_dir("marker_interrupt_quiet");
  const fs::path errors = fresh_temp_dir("marker_interrupt_quiet_err") / "stderr.txt";
  const Stopped s = interrupt_after({"gcode", rows("The quick brown fox jumps over the lazy dog", 40), "--mode",
                                     "protrusion", "--height", "5", "--tool-diameter", "0.5", "--quiet", "-o",
                                     (dir / "plate.ngc").string()},
                                    std::chrono::milliseconds(1500), errors);
  ASSERT_TRUE(s.exited);
  EXPECT_EQ(s.code, 130);
  // One line: no progress, only the interruption.
  EXPECT_EQ(std::count(s.err.begin(), s.err.end(), '\n'), 1) << s.err;
  EXPECT_EQ(s.err.rfind("marker: interrupted while ", 0), 0u) << s.err;
  expect_empty(dir);
}

TEST(Interrupt, HeadTestPatternStopsWithNothingWritten) {
  // Marking and photographing the lag pattern takes about 2 s; neither the pattern file nor the
  // picture may appear.
  const fs::path dir = fresh_temp_dir("marker_interrupt_pattern");
  const fs::path errors = fresh_temp_dir("marker_interrupt_pattern_err") / "stderr.txt";
  const Stopped s = interrupt_after({"head", "test-pattern", "-o", (dir / "p.json").string(), "--picture",
                                     (dir / "p.png").string()},
                                    std::chrono::milliseconds(600), errors);
  ASSERT_TRUE(s.exited) << "killed by the signal instead of stopping";
  EXPECT_EQ(s.code, 130);
  EXPECT_NE(s.err.find("marker: interrupted while marking and photographing the lag pattern"), std::string::npos)
      << s.err;
  EXPECT_NE(s.err.find("; nothing was written\n"), std::string::npos) << s.err;
  expect_empty(dir);
}

TEST(Interrupt, PeenAndPreviewStopWithNothingWritten) {
  const fs::path dir = fresh_temp_dir("marker_interrupt_peen");
  const fs::path errors = fresh_temp_dir("marker_interrupt_peen_err") / "stderr.txt";
  // Continuous dots along 80 rows of a stroke font (47 761 dots, near the plan's limit), routed
  // by all three planners (--compare): over two seconds of work on an idle 2-core machine since
  // the optimiser became O(N log N), so the signal at 0.8 s always finds it working.
  const Stopped peen = interrupt_after({"peen", rows("SERIAL 2026-000123 LOT 42", 80), "--font", "builtin", "--height",
                                        "3", "--pitch", "0.25", "--field", "1000", "--compare", "--quiet", "-o",
                                        (dir / "plan.csv").string(), "--preview", (dir / "plan.svg").string()},
                                       std::chrono::milliseconds(800), errors);
  ASSERT_TRUE(peen.exited);
  EXPECT_EQ(peen.code, 130) << peen.err;
  EXPECT_NE(peen.err.find("marker: interrupted while "), std::string::npos) << peen.err;
  expect_empty(dir);

  // A long text at a size that makes a large PNG.
  const Stopped preview = interrupt_after({"preview", rows(std::string(200, 'M'), 300), "--height", "0.5", "--field",
                                           "500", "--quiet", "-o", (dir / "text.png").string()},
                                          std::chrono::milliseconds(500), errors);
  ASSERT_TRUE(preview.exited);
  EXPECT_EQ(preview.code, 130) << preview.err;
  EXPECT_NE(preview.err.find("marker: interrupted while "), std::string::npos) << preview.err;
  expect_empty(dir);
}

}  // namespace
}  // namespace mark::test

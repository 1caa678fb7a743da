// Every `$M …` command in the README's shell blocks runs as written, from a checkout's root (the
// example pictures are under examples/), and ends with the exit status its comment promises — so
// a newcomer who copies a line never meets an option that was renamed or a file that is not there.
// Commands that need a real LMC board are listed, with why, and not run.
#include <gtest/gtest.h>

#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "tests/marker/cli_runner.hpp"

namespace mark {
namespace {

namespace fs = std::filesystem;

// The words of a shell line as sh splits them: "…" and '…' quoted, a # after a blank starts a
// comment. Enough for the README's lines (no variables but $M, no escapes outside quotes).
std::vector<std::string> shell_words(const std::string& line) {
  std::vector<std::string> words;
  std::string word;
  bool in_word = false;
  char quote = 0;
  for (std::size_t i = 0; i < line.size(); ++i) {
    const char c = line[i];
    if (quote) {
      if (c == quote) quote = 0;
      else word += c;
    } else if (c == '"' || c == '\'') {
      quote = c;
      in_word = true;
    } else if (c == ' ' || c == '\t') {
      if (in_word) words.push_back(word);
      word.clear();
      in_word = false;
    } else if (c == '#' && !in_word) {
      break;
    } else {
      word += c;
      in_word = true;
    }
  }
  if (in_word) words.push_back(word);
  return words;
}

// The `$M …` lines of the README's ```sh blocks, as words after $M.
std::vector<std::vector<std::string>> readme_commands() {
  std::ifstream in(std::string(MARKER_SOURCE_DIR) + "/README.md");
  std::vector<std::vector<std::string>> commands;
  bool in_sh = false;
  for (std::string line; std::getline(in, line);) {
    if (line.starts_with("```")) {
      in_sh = line == "```sh";
      continue;
    }
    if (in_sh && line.starts_with("$M ")) {
      std::vector<std::string> words = shell_words(line);
      words.erase(words.begin());
      commands.push_back(words);
    }
  }
  return commands;
}

std::string joined(const std::vector<std::string>& words) {
  std::string s;
  for (const std::string& w : words) s += (s.empty() ? "" : " ") + w;
  return s;
}

// Why a command cannot run here: it talks to a real board (none in CI).
std::string needs_a_board(const std::vector<std::string>& words) {
  if (words[0] == "devices") return "lists the USB boards";
  if (words[0] == "frame") return "drives the red pointer of a board";
  if (words[0] == "lmc") return "probes a board";
  for (std::size_t i = 0; i + 1 < words.size(); ++i)
    if (words[i] == "--device" && (words[i + 1] == "lmc" || words[i + 1].starts_with("lmc:")))
      return "marks on a board";
  return "";
}

TEST(ReadmeCommands, EveryCommandRunsAsWrittenWithTheStatusItsCommentPromises) {
  const std::vector<std::vector<std::string>> commands = readme_commands();
  ASSERT_GE(commands.size(), 25u) << "the README's command lines were not found";
  const fs::path dir = test::fresh_temp_dir("marker_readme_commands");
  test::use_station_state(dir);
  fs::create_directories(dir / "examples");
  for (const char* picture : {"shadow.png", "photo.png", "type.png"})
    fs::copy_file(fs::path(MARKER_SOURCE_DIR) / "examples" / picture, dir / "examples" / picture);
  // The lines whose point is a fault, with the status they end with (docs/json.md: 0 done,
  // 1 failed, 130 aborted).
  const std::map<std::string, int> expected_status = {
      {"mark SN 0042 --inject underrun@5000 --trace t.csv", 1},
  };
  const fs::path before = fs::current_path();
  fs::current_path(dir);
  int ran = 0;
  std::set<std::string> skipped;
  for (const std::vector<std::string>& words : commands) {
    const std::string line = joined(words);
    SCOPED_TRACE(line);
    if (const std::string why = needs_a_board(words); !why.empty()) {
      skipped.insert(words[0] + ": " + why);
      continue;
    }
    const test::CliResult r = test::run_cli(words);
    const auto it = expected_status.find(line);
    EXPECT_EQ(r.code, it == expected_status.end() ? 0 : it->second) << r.err.substr(0, 2000);
    ++ran;
  }
  fs::current_path(before);
  EXPECT_GE(ran, 25);
  // Only the board's commands are left out: devices, lmc probe, frame, mark on lmc.
  EXPECT_LE(skipped.size(), 4u);
  // What the commands wrote is there.
  for (const char* written : {"lot.png", "t.csv", "sl10.json", "plate.svg", "seal.png", "acme.ngc", "acme.svg",
                              "ag.ngc", "proof.png", "bracket.json", "job.lmc"})
    EXPECT_GT(fs::exists(dir / written) ? fs::file_size(dir / written) : 0, 0u) << written;
}

}  // namespace
}  // namespace mark

#pragma once
// Runs the `marker` command line in-process and captures what it prints, for the CLI tests.
#include <gtest/gtest.h>

#include <stdlib.h>

#include <filesystem>
#include <string>
#include <vector>

#include "marker/cli/cli.hpp"

namespace mark::test {

struct CliResult {
  int code;
  std::string out;
  std::string err;
};

inline CliResult run_cli(std::vector<std::string> args) {
  args.insert(args.begin(), "marker");
  std::vector<char*> argv;
  for (std::string& a : args) argv.push_back(a.data());
  testing::internal::CaptureStdout();
  testing::internal::CaptureStderr();
  const int code = cli::run(static_cast<int>(argv.size()), argv.data());
  return {code, testing::internal::GetCapturedStdout(), testing::internal::GetCapturedStderr()};
}

// `marker mark --job JOB --virtual-time --station line-1 EXTRA…`: a production run of the tests.
inline CliResult run_mark_job(const std::string& job, const std::vector<std::string>& extra) {
  std::vector<std::string> args{"mark", "--job", job, "--virtual-time", "--station", "line-1"};
  args.insert(args.end(), extra.begin(), extra.end());
  return run_cli(args);
}

// The station's state (its default serial store, its outcome journals) in `dir`/state, so a
// test's production commands meet a store of their own (marker/store/store_location.hpp).
inline std::filesystem::path use_station_state(const std::filesystem::path& dir) {
  const std::filesystem::path state = dir / "state";
  ::unsetenv("STATE_DIRECTORY");
  ::setenv("XDG_STATE_HOME", state.c_str(), 1);
  return state / "marker";
}

// `folder` under the temporary directory, narrowed to the running test (Suite.Name): CTest runs
// every test in a process of its own, two at a time, so a folder two tests shared was emptied by
// one while the other wrote into it.
inline std::filesystem::path per_test_temp_dir(const std::string& folder) {
  std::filesystem::path dir = std::filesystem::temp_directory_path() / folder;
  if (const auto* info = testing::UnitTest::GetInstance()->current_test_info()) {
    std::string name = std::string(info->test_suite_name()) + "." + info->name();
    for (char& c : name)
      if (c == '/') c = '_';
    dir /= name;
  }
  return dir;
}

// A per-test temporary folder, empty.
inline std::filesystem::path fresh_temp_dir(const std::string& folder) {
  const std::filesystem::path dir = per_test_temp_dir(folder);
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir;
}

// A path in the test's temporary folder, with no file there yet.
inline std::filesystem::path fresh_temp_file(const std::string& folder, const std::string& name) {
  const std::filesystem::path dir = per_test_temp_dir(folder);
  std::filesystem::create_directories(dir);
  std::filesystem::remove(dir / name);
  return dir / name;
}

}  // namespace mark::test

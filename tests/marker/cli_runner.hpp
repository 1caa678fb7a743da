#pragma once
// Runs the `marker` command line in-process and captures what it prints, for the CLI tests.
#include <gtest/gtest.h>

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

}  // namespace mark::test
